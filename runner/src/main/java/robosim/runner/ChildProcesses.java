package robosim.runner;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * Starts Java child processes on this JVM's class path and stops them all at the end, or when this JVM
 * is stopped (SIGTERM, Ctrl-C: a shutdown hook), so that killing a runner never leaves its children.
 */
final class ChildProcesses implements AutoCloseable {
    private final List<Process> started = new CopyOnWriteArrayList<>();
    private final List<String> names = new ArrayList<>();
    private final String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
    private final String classPath = System.getProperty("java.class.path");
    private final List<String> jvmOptions;
    private final Thread stopOnExit = new Thread(this::stopAll, "stop-children");

    ChildProcesses(List<String> jvmOptions) {
        this.jvmOptions = List.copyOf(jvmOptions);
        Runtime.getRuntime().addShutdownHook(stopOnExit);
    }

    /**
     * Starts {@code mainClass} with {@code args}. Its stderr goes to ours; its stdout lines go to
     * {@code stdoutLines} (on a pipe thread), or to our stderr when null.
     */
    Process start(String name, String mainClass, List<String> args, Consumer<String> stdoutLines) throws IOException {
        return start(name, List.of(), mainClass, args, stdoutLines);
    }

    /** As above, with JVM options for this child before the common ones (which may override them). */
    Process start(String name, List<String> ownOptions, String mainClass, List<String> args,
            Consumer<String> stdoutLines) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(java);
        cmd.addAll(ownOptions);
        cmd.addAll(jvmOptions);
        cmd.add("-cp");
        cmd.add(classPath);
        cmd.add(mainClass);
        cmd.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.redirectError(ProcessBuilder.Redirect.INHERIT);
        Process p = pb.start();
        started.add(p);
        names.add(name);
        Consumer<String> sink = stdoutLines != null ? stdoutLines : System.err::println;
        Thread pipe = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    sink.accept(line);
                }
            } catch (IOException ignored) {
                // the child is gone
            }
        }, "pipe[" + name + "]");
        pipe.setDaemon(true);
        pipe.start();
        return p;
    }

    /** Starts a child that is not waited for nor stopped at the end (a viewer window the user closes). */
    void startDetached(String name, String mainClass, List<String> args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(java, "-cp", classPath, mainClass));
        cmd.addAll(args);
        new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
    }

    /** Waits up to {@code seconds} for every child; returns the names of those that failed or hung. */
    List<String> awaitAll(long seconds) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        List<String> bad = new ArrayList<>();
        for (int i = 0; i < started.size(); i++) {
            Process p = started.get(i);
            long left = Math.max(0, deadline - System.nanoTime());
            if (!p.waitFor(left, TimeUnit.NANOSECONDS)) {
                bad.add(names.get(i) + " (still running)");
            } else if (p.exitValue() != 0) {
                bad.add(names.get(i) + " (exit " + p.exitValue() + ")");
            }
        }
        return bad;
    }

    /** Kills the child started under {@code name} at once (for fault injection). */
    void kill(String name) {
        for (int i = 0; i < names.size(); i++) {
            if (names.get(i).equals(name)) {
                started.get(i).destroyForcibly();
            }
        }
    }

    @Override
    public void close() {
        stopAll();
        try {
            Runtime.getRuntime().removeShutdownHook(stopOnExit);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is stopping: the hook runs stopAll anyway
        }
    }

    private void stopAll() {
        for (Process p : started) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
    }
}
