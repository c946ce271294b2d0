package robosim.runner;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.regex.Pattern;

/**
 * Starts Java child processes on this JVM's class path and stops them all at the end: when closed,
 * and when this JVM is told to stop (SIGTERM, SIGINT, SIGHUP: a shutdown hook, thread "stop-children"),
 * so that killing a runner never leaves its children running.
 * Safe to use from the runner's thread and the JVM's shutdown thread at once.
 */
public final class ChildProcesses implements AutoCloseable {
    /** How long children get to end after SIGTERM before they are killed. */
    private static final long GRACE_MS = 5000;

    /** A started child, with the last lines it wrote to stderr (its reason, when it fails). */
    static final class Child {
        private static final int KEPT_LINES = 3;
        final String name;
        final Process process;
        private final ClassDataArchives.Launch archive;
        private final java.util.ArrayDeque<String> lastErrorLines = new java.util.ArrayDeque<>();
        /** Its {@code robot NAME: its control code failed: ...} lines, every one (up to one per robot it runs). */
        private final List<String> controlFailed = new ArrayList<>();
        private final java.util.concurrent.CountDownLatch stderrClosed = new java.util.concurrent.CountDownLatch(1);

        private Child(String name, Process process, ClassDataArchives.Launch archive) {
            this.name = name;
            this.process = process;
            this.archive = archive;
        }

        private synchronized void errorLine(String line) {
            if (CONTROL_FAILED.matcher(line).matches() && controlFailed.size() < MAX_CONTROL_FAILED) {
                controlFailed.add(line.strip());
            }
            if (lastErrorLines.size() == KEPT_LINES) {
                lastErrorLines.removeFirst();
            }
            lastErrorLines.addLast(line.strip());
        }

        /**
         * Its last (up to three) non-blank stderr lines, joined by " | ", once its stderr has closed
         * (every line it wrote has been read) or after {@code timeoutMs}.
         */
        String lastErrorLines(long timeoutMs) throws InterruptedException {
            stderrClosed.await(timeoutMs, TimeUnit.MILLISECONDS);
            synchronized (this) {
                return String.join(" | ", lastErrorLines);
            }
        }

        /** Its control-failed lines, once its stderr has closed or after {@code timeoutMs}. */
        List<String> controlFailed(long timeoutMs) throws InterruptedException {
            stderrClosed.await(timeoutMs, TimeUnit.MILLISECONDS);
            synchronized (this) {
                return List.copyOf(controlFailed);
            }
        }
    }

    private final List<Child> started = new CopyOnWriteArrayList<>();
    /**
     * Netty (the control and web links) and msgpack-core (the robot link) would warn about sun.misc.Unsafe on JDK 24
     * and later: both without it.
     */
    static final List<String> NO_UNSAFE = List.of("-Dio.netty.noUnsafe=true", "-Dmsgpack.universal-buffer=true");
    private final String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
    private final String classPath = System.getProperty("java.class.path");
    private final List<String> jvmOptions;
    private final ClassDataArchives archives = ClassDataArchives.fromEnvironment();
    private final Thread onSignal = new Thread(this::close, "stop-children");
    /** Whether this JVM was told to stop (a signal), and so stopped the children: their exits are no failure. */
    private volatile boolean stoppedBySignal;
    /** Set once {@link #close} has begun: a child started after that is stopped at once (guarded by {@code this}). */
    private boolean closed;

    /** Children with these JVM options (after each child's own); stopped on close and when this JVM is told to stop. */
    public ChildProcesses(List<String> jvmOptions) {
        this.jvmOptions = List.copyOf(jvmOptions);
        Runtime.getRuntime().addShutdownHook(onSignal);
    }

    /**
     * Starts {@code mainClass} with {@code args}, and JVM options for this child before the common ones
     * (which may override them), after those of its class-data archive ({@link ClassDataArchives}). Its
     * stderr is copied to ours; its stdout lines go to {@code stdoutLines} (on a pipe thread), or to our
     * stderr when null.
     */
    Process start(String name, List<String> ownOptions, String mainClass, List<String> args,
            Consumer<String> stdoutLines) throws IOException {
        return startChild(name, ownOptions, mainClass, args, stdoutLines).process;
    }

    /** As above, returning the child with its last stderr line. */
    Child startChild(String name, List<String> ownOptions, String mainClass, List<String> args,
            Consumer<String> stdoutLines) throws IOException {
        List<String> options = new ArrayList<>(ownOptions);
        options.addAll(jvmOptions);
        ClassDataArchives.Launch archive = archives.launch(mainClass, classPath, options);
        Child child = new Child(name, startOrFinish(new ProcessBuilder(command(archive, options, mainClass, args)),
                archive), archive);
        keep(child);
        pipe(name + ".out", child.process.getInputStream(), stdoutLines != null ? stdoutLines : System.err::println,
                () -> { });
        pipe(name + ".err", child.process.getErrorStream(), line -> {
            if (!CONTROL_FAILED.matcher(line).matches()) { // (said once, at the end: controlFailures)
                System.err.println(line);
            }
            if (!line.isBlank()) {
                child.errorLine(line);
            }
        }, child.stderrClosed::countDown);
        return child;
    }

    /**
     * A robot process's last line when a robot's control code threw: not copied to our stderr, where its log's error
     * (with the stack trace) is already, since the runner says it once at the end ({@link #controlFailures}).
     */
    /** The most control-failed lines kept of one child (one per robot it runs; a bound all the same). */
    private static final int MAX_CONTROL_FAILED = 10_000;
    private static final Pattern CONTROL_FAILED = Pattern.compile(
            "robot \\S+: its control code failed: .*");

    /**
     * Starts {@code mainClass} with {@code args} and the common JVM options, its stdout and stderr into {@code log}
     * (a new file) rather than ours, and puts its class-data archive in place as soon as it has exited (a sweep
     * starts hundreds, one after another).
     */
    public Process startLogged(String name, String mainClass, List<String> args, Path log) throws IOException {
        ClassDataArchives.Launch archive = archives.launch(mainClass, classPath, jvmOptions);
        ProcessBuilder builder = new ProcessBuilder(command(archive, jvmOptions, mainClass, args))
                .redirectErrorStream(true).redirectOutput(log.toFile());
        Child child = new Child(name, startOrFinish(builder, archive), archive);
        keep(child);
        child.process.onExit().thenRun(() -> {
            archive.finish();
            started.remove(child); // (a sweep's runs: thousands, each waited for by its caller)
        });
        return child.process;
    }

    /**
     * Starts a warm JVM (main class {@code mainClass}, a run host) with the common JVM options and its class-data archive: its stdout lines go
     * to {@code stdoutLines} (and {@code atEnd} runs at the end of its stdout, when it has exited), its stderr is
     * kept (its last lines, {@link Child#lastErrorLines}), not copied to ours: its runs write into their logs, and
     * what the JVM itself says as it dies (out of memory) is the reason of the run it broke.
     */
    Child startWorker(String name, String mainClass, Consumer<String> stdoutLines, Runnable atEnd) throws IOException {
        List<String> options = new ArrayList<>(jvmOptions);
        options.add("-XX:+ExitOnOutOfMemoryError"); // (a JVM short of memory anywhere runs nothing more)
        ClassDataArchives.Launch archive = archives.launch(mainClass, classPath, options, false);
        Child child = new Child(name, startOrFinish(new ProcessBuilder(command(archive, options, mainClass,
                List.of())), archive), archive);
        keep(child);
        child.process.onExit().thenRun(() -> {
            archive.finish();
            started.remove(child);
        });
        pipe(name + ".out", child.process.getInputStream(), stdoutLines, atEnd);
        pipe(name + ".err", child.process.getErrorStream(), line -> {
            if (!line.isBlank()) {
                child.errorLine(line);
            }
        }, child.stderrClosed::countDown);
        return child;
    }

    /** True once {@link #close} has begun (this JVM stopping, or its owner done). */
    public synchronized boolean closing() {
        return closed;
    }

    /**
     * Adds a started child to those {@link #close} stops; when close has begun already (a child started while this
     * JVM is being stopped), stops it at once and says so.
     */
    private void keep(Child child) throws IOException {
        boolean late;
        synchronized (this) {
            late = closed;
            if (!late) {
                started.add(child);
            }
        }
        if (late) {
            child.process.descendants().forEach(ProcessHandle::destroyForcibly);
            child.process.destroyForcibly();
            child.archive.finish();
            throw new IOException(child.name + ": started while every child is being stopped; stopped at once");
        }
    }

    private List<String> command(ClassDataArchives.Launch archive, List<String> options, String mainClass,
            List<String> args) {
        List<String> cmd = new ArrayList<>();
        cmd.add(java);
        cmd.addAll(NO_UNSAFE);
        cmd.addAll(robosim.protocol.LogLevel.jvmOptions());
        cmd.addAll(archive.options());
        cmd.addAll(options);
        cmd.add("-cp");
        cmd.add(classPath);
        cmd.add(mainClass);
        cmd.addAll(args);
        return cmd;
    }

    /** Starts {@code builder}'s command; when it cannot start, its archive claim is dropped at once. */
    private static Process startOrFinish(ProcessBuilder builder, ClassDataArchives.Launch archive) throws IOException {
        try {
            return builder.start();
        } catch (IOException | RuntimeException e) {
            archive.finish();
            throw e;
        }
    }

    /** Copies {@code stream}'s lines to {@code sink} on a thread of its own; {@code atEnd} runs at its end. */
    private static void pipe(String name, InputStream stream, Consumer<String> sink, Runnable atEnd) {
        Thread pipe = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(stream, StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    sink.accept(line);
                }
            } catch (IOException ignored) {
                // the child is gone
            } finally {
                atEnd.run();
            }
        }, "pipe[" + name + "]");
        pipe.setDaemon(true);
        pipe.start();
    }

    /** Starts a child that is not waited for nor stopped at the end (a viewer window the user closes). */
    void startDetached(String name, String mainClass, List<String> args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(java));
        cmd.addAll(NO_UNSAFE);
        cmd.addAll(List.of("-cp", classPath, mainClass));
        cmd.addAll(args);
        new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
    }

    /** Waits up to {@code seconds} for every child; returns the names of those that failed or hung. */
    List<String> awaitAll(long seconds) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        List<String> bad = new ArrayList<>();
        for (Child c : started) {
            long left = Math.max(0, deadline - System.nanoTime());
            if (!c.process.waitFor(left, TimeUnit.NANOSECONDS)) {
                bad.add(c.name + " (still running)");
            } else if (c.process.exitValue() != 0) {
                bad.add(c.name + " (exit " + c.process.exitValue() + ")");
            }
        }
        return bad;
    }

    /**
     * After {@link #awaitAll}: what the robot processes that ended with {@link #EXIT_CONTROL_FAILED} said of it, one
     * {@code robot NAME: its control code failed: ...} line for each robot whose control code threw.
     */
    List<String> controlFailures() throws InterruptedException {
        List<String> lines = new ArrayList<>();
        for (Child c : started) {
            if (!c.process.isAlive() && c.process.exitValue() == EXIT_CONTROL_FAILED) {
                int before = lines.size();
                lines.addAll(c.controlFailed(5_000));
                if (lines.size() == before) { // (it said something else: it still counts)
                    lines.add(c.name + ": its control code failed (exit " + EXIT_CONTROL_FAILED + "; its log says how)");
                }
            }
        }
        return lines;
    }

    /** A robot process's exit code when its run went on but a robot's control code threw out of {@code run}. */
    static final int EXIT_CONTROL_FAILED = robosim.hardware.HardwareSimulator.EXIT_CONTROL_FAILED;

    /** Kills the child started under {@code name} at once (for fault injection). */
    void kill(String name) {
        for (Child c : started) {
            if (c.name.equals(name)) {
                c.process.destroyForcibly();
            }
        }
    }

    /** Whether this JVM was told to stop (SIGTERM, SIGINT, SIGHUP) and stopped the children itself. */
    boolean stoppedBySignal() {
        return stoppedBySignal;
    }

    /**
     * Asks every child still running (and its children) to stop with SIGTERM, so the Environment can
     * tell its clients; kills what is left after a grace period; then puts in place the class-data
     * archives the ended children wrote. Idempotent.
     */
    @Override
    public void close() {
        synchronized (this) {
            closed = true;
        }
        if (Thread.currentThread() == onSignal) {
            stoppedBySignal = true;
        }
        List<ProcessHandle> all = new ArrayList<>();
        for (Child c : started) {
            c.process.descendants().forEach(all::add);
            all.add(c.process.toHandle());
        }
        all.forEach(ProcessHandle::destroy);
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(GRACE_MS);
        for (ProcessHandle h : all) {
            try {
                h.onExit().get(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (Exception stillRunning) {
                h.destroyForcibly();
            }
        }
        for (Child c : started) {
            if (!c.process.isAlive()) {
                c.archive.finish();
            }
        }
        if (Thread.currentThread() != onSignal) {
            try {
                Runtime.getRuntime().removeShutdownHook(onSignal);
            } catch (IllegalStateException shuttingDown) {
                // the hook is running or about to: it finds every child gone
            }
        }
    }
}
