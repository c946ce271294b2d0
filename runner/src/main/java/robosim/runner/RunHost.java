package robosim.runner;

import java.io.BufferedReader;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A warm JVM's runs: headless runs ({@link HeadlessRunner}, any layout) one after another in this JVM, each as if
 * it were the only one. Each run's output (what {@code headless.sh} would print, and its log) goes into a file of
 * its own; its control classes are loaded by a {@link ControlClassLoader} of its own (the context class loader of
 * its threads), so the static state of control code never reaches the next run; everything the run made (threads,
 * ports, files, recordings) is released by the runner as at a JVM's end. After the run the host looks for what
 * the run left behind: a platform thread the run started (one with the run's class loader as its context loader,
 * but not one of the JDK's own system threads a run may start, such as the process reaper, which copies it on JDK
 * 17) still alive a few seconds after its end, or control code
 * still running. A JVM with such a leftover must not run again: its run counts as failed, with that reason, and
 * the JVM ends ({@link HeadlessRuns.Ended#broke()}). A virtual thread that control code starts itself and leaves
 * running is not seen (the JDK lists no virtual threads): it lives on in the worker.
 *
 * <p>As a process ({@code main}: a sweep's worker, {@link WarmWorker} on the other side) it reads one run per line
 * on stdin ({@code run TAB LOG TAB ARG TAB ARG ...}, the fields free of tabs and line breaks) and answers each on
 * stdout ({@code ended TAB CODE}, or {@code broke TAB CODE TAB REASON} before it exits); it ends at the end of its
 * stdin. Its stdout carries the answers only: {@code System.out} is its stderr between runs. It is started by
 * RoboSim, never by hand: its stdin is its owner's. Threads: {@code main} (reads the requests, answers),
 * {@code run} (one run at a time: the runner's {@code main}).
 */
public final class RunHost {
    /** How long the threads a run started get to end after it, ms (a robot process's grace, and some). */
    private static final long LEFTOVER_GRACE_MS = 5_000;
    private final List<Path> controlPath;

    /** A host whose runs' control classes come from {@code controlPath} (the user's class path) or RoboSim's examples. */
    public RunHost(List<Path> controlPath) {
        this.controlPath = List.copyOf(controlPath);
    }

    /**
     * Runs {@code headless.sh args} in this JVM, its output into {@code log} (created, or emptied); returns its exit
     * code and, when it left something running, what (this JVM must then run no more).
     */
    public HeadlessRuns.Ended run(List<String> args, Path log) throws IOException, InterruptedException {
        PrintStream out = System.out;
        PrintStream err = System.err;
        HeadlessRunner runner = new HeadlessRunner();
        int[] code = {1};
        try (OutputStream file = Files.newOutputStream(log, StandardOpenOption.CREATE,
                StandardOpenOption.TRUNCATE_EXISTING, StandardOpenOption.WRITE);
             PrintStream logged = new PrintStream(file, true, StandardCharsets.UTF_8);
             ControlClassLoader classes = new ControlClassLoader("run", controlPath, RunHost.class.getClassLoader())) {
            Thread run = new Thread(() -> code[0] = HeadlessRunner.commandLine(runner)
                    .execute(args.toArray(new String[0])), "run");
            run.setContextClassLoader(classes);
            List<String> left;
            System.setOut(logged);
            System.setErr(logged);
            try {
                run.start();
                run.join();
                left = leftover(classes); // (what they print meanwhile still goes into the run's log)
            } finally {
                System.setOut(out);
                System.setErr(err);
            }
            List<String> running = runner.controlStillRunning();
            String broke = !running.isEmpty() ? "the control code of " + String.join(", ", running)
                    + " was still running after the run's end (a warm JVM cannot stop it: --fresh-jvm-per-run)"
                    : !left.isEmpty() ? "the run left threads running " + LEFTOVER_GRACE_MS / 1000 + " s after its end: "
                    + String.join(", ", left) + " (a warm JVM cannot stop them: --fresh-jvm-per-run)" : null;
            if (broke != null) {
                logged.println("warm JVM: " + broke);
            }
            return new HeadlessRuns.Ended(code[0], broke);
        }
    }

    /**
     * The threads the run started (their context class loader its own; a thread started from a virtual thread is in no
     * group of the run's) that are still alive once those that end have had {@link #LEFTOVER_GRACE_MS} to; not the
     * JDK's system threads (of the root thread group), which a run may start and which may copy its loader.
     */
    private static List<String> leftover(ClassLoader runs) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(LEFTOVER_GRACE_MS);
        List<String> left = new ArrayList<>();
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            ThreadGroup group = t.getThreadGroup();
            if (t.getContextClassLoader() == runs && group != null && group.getParent() != null) {
                t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
                if (t.isAlive()) {
                    left.add(robosim.protocol.Printable.of(t.getName(), 80));
                }
            }
        }
        return left;
    }

    /** The request line for a run of {@code args} into {@code log}. */
    static String request(Path log, List<String> args) {
        List<String> fields = new ArrayList<>(List.of("run", log.toString()));
        fields.addAll(args);
        for (String f : fields) {
            if (f.indexOf('\t') >= 0 || f.indexOf('\n') >= 0 || f.indexOf('\r') >= 0) {
                throw new IllegalArgumentException("a warm run's argument may hold no tab or line break: "
                        + robosim.protocol.Printable.of(f, 100));
            }
        }
        return String.join("\t", fields);
    }

    /** The answer line for {@code ended}. */
    static String answer(HeadlessRuns.Ended ended) {
        return ended.broke() == null ? "ended\t" + ended.code()
                : "broke\t" + ended.code() + "\t" + ended.broke().replaceAll("[\\t\\r\\n]", " ");
    }

    /** An answer line read back; null if it is none. */
    static HeadlessRuns.Ended parseAnswer(String line) {
        String[] f = line.split("\t", 3);
        if (f.length < 2 || !f[1].matches("-?[0-9]{1,10}")) {
            return null;
        }
        int code = Integer.parseInt(f[1]);
        return f[0].equals("ended") && f.length == 2 ? new HeadlessRuns.Ended(code, null)
                : f[0].equals("broke") && f.length == 3 ? new HeadlessRuns.Ended(code, f[2]) : null;
    }

    public static void main(String[] args) throws IOException, InterruptedException {
        if (args.length > 0) {
            System.err.println("run host: a sweep's warm JVM, started by scripts/sweep.sh; it takes no argument");
            System.exit(2);
        }
        // the answers go to the stdout this JVM was started with, and nothing else does: the runs' output to their
        // logs, anything printed between runs (a thread of a run that is late) to stderr
        PrintStream answers = new PrintStream(new FileOutputStream(FileDescriptor.out), true, StandardCharsets.UTF_8);
        System.setOut(System.err);
        RunHost host = new RunHost(ControlClassLoader.entries(System.getenv("ROBOSIM_CLASSPATH")));
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            String[] f = line.split("\t", -1);
            if (f.length < 2 || !f[0].equals("run")) {
                System.err.println("run host: not a request: " + robosim.protocol.Printable.of(line, 100));
                System.exit(2);
            }
            HeadlessRuns.Ended ended;
            try {
                ended = host.run(Arrays.asList(f).subList(2, f.length), Path.of(f[1]));
            } catch (IOException | RuntimeException e) { // (the host's, not the run's: its log, its class path)
                ended = new HeadlessRuns.Ended(1, "the warm JVM could not run it: " + e);
            }
            answers.println(answer(ended));
            if (ended.broke() != null) {
                System.exit(1); // (what the run left goes with this JVM)
            }
        }
        System.exit(0); // (the end of the requests: nothing of a run's is left to wait for)
    }
}
