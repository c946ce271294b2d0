package robosim.runner;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * Where headless runs run, one at a time: each in a fresh JVM of its own ({@link #freshJvms}), or one after another
 * in a warm JVM ({@link WarmWorker}). The same run gives the same output either way (but its wall time).
 */
public interface HeadlessRuns extends AutoCloseable {
    /**
     * Runs {@code headless.sh args}, its output into {@code log} (created, or emptied); returns how it ended. Gives
     * up on a run still going {@code patienceS} after it started (0: never), ending what ran it.
     */
    Ended run(String name, List<String> args, Path log, long patienceS) throws IOException, InterruptedException;

    /** Ends what runs the runs (a warm JVM); a run going on is stopped. */
    @Override
    void close();

    /**
     * How a run ended.
     *
     * @param code its exit code ({@code headless.sh}'s; from 128 up, the signal that ended its JVM)
     * @param broke why the JVM that ran it could not go on (it exited or was killed during the run, or the run left
     *        threads running), or null; a run that broke its JVM has failed, whatever its code
     */
    record Ended(int code, String broke) {
    }

    /** Each run in a JVM of its own, started by {@code children} (the sweep's runs before warm JVMs; isolation). */
    static HeadlessRuns freshJvms(ChildProcesses children) {
        return new HeadlessRuns() {
            @Override
            public Ended run(String name, List<String> args, Path log, long patienceS)
                    throws IOException, InterruptedException {
                Process process = children.startLogged(name, "robosim.runner.HeadlessRunner", args, log);
                try {
                    if (patienceS > 0 && !process.waitFor(patienceS, java.util.concurrent.TimeUnit.SECONDS)) {
                        process.destroyForcibly();
                        return new Ended(process.waitFor(), "no end within " + patienceS + " s; its JVM was stopped");
                    }
                    return new Ended(process.waitFor(), null);
                } catch (InterruptedException e) {
                    process.destroy();
                    throw e;
                }
            }

            @Override
            public void close() {
            }
        };
    }
}
