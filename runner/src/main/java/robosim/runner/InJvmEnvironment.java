package robosim.runner;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.text.ParseException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import jdk.jfr.Configuration;
import jdk.jfr.Recording;
import robosim.environment.EnvironmentServer;

/**
 * {@code headless.sh --one-jvm}'s Environment: {@link EnvironmentServer} run from its plan in the runner's own JVM, on thread
 * {@code environment}, its lines handed to the runner as a child's would be; seen by the runner as the
 * {@link Process} an Environment child would be (its exit code, its end), so a run has one JVM to start,
 * not two. With {@code --profile DIR} this JVM records a flight recording into {@code DIR/environment.jfr}.
 */
final class InJvmEnvironment extends Process {
    private final CompletableFuture<Process> exited = new CompletableFuture<>();
    private final Thread thread;
    private volatile int code = -1;

    private InJvmEnvironment(EnvironmentServer.Plan plan, Consumer<String> lines, Path profile) {
        thread = new Thread(() -> {
            Recording recording = null;
            try {
                recording = profile == null ? null : record(profile);
                code = EnvironmentServer.run(plan, lines);
            } catch (IOException | ParseException | RuntimeException | InterruptedException e) {
                System.err.println("headless: the Environment failed: " + e);
                code = 1;
            } finally {
                if (recording != null) {
                    recording.stop(); // (written to its destination)
                    recording.close();
                }
                exited.complete(this);
            }
        }, "environment");
    }

    /** Starts the Environment of {@code plan}; its lines go to {@code lines}. */
    static InJvmEnvironment start(EnvironmentServer.Plan plan, Consumer<String> lines, Path profile) {
        InJvmEnvironment e = new InJvmEnvironment(plan, lines, profile);
        e.thread.start();
        return e;
    }

    private static Recording record(Path dir) throws IOException, ParseException {
        Files.createDirectories(dir);
        Recording r = new Recording(Configuration.getConfiguration("profile"));
        r.setDestination(dir.resolve("environment.jfr").toAbsolutePath());
        r.start();
        return r;
    }

    @Override
    public CompletableFuture<Process> onExit() {
        return exited;
    }

    @Override
    public int waitFor() throws InterruptedException {
        try {
            exited.get();
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        }
        return code;
    }

    @Override
    public boolean waitFor(long timeout, TimeUnit unit) throws InterruptedException {
        try {
            exited.get(timeout, unit);
            return true;
        } catch (TimeoutException e) {
            return false;
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        }
    }

    @Override
    public int exitValue() {
        if (!exited.isDone()) {
            throw new IllegalThreadStateException("the Environment has not ended");
        }
        return code;
    }

    @Override
    public boolean isAlive() {
        return !exited.isDone();
    }

    /** The runner is giving up: the JVM's end (the runner exits next) ends it; its shutdown hook stops the run. */
    @Override
    public void destroy() {
        thread.interrupt();
    }

    @Override
    public OutputStream getOutputStream() {
        return OutputStream.nullOutputStream();
    }

    @Override
    public InputStream getInputStream() {
        return InputStream.nullInputStream();
    }

    @Override
    public InputStream getErrorStream() {
        return InputStream.nullInputStream();
    }
}
