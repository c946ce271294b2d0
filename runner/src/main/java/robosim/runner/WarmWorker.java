package robosim.runner;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A warm JVM ({@link RunHost}) seen from its owner, a sweep's pool thread or a Slurm task: runs one headless run at
 * a time in it, so that a sweep pays a JVM's start, its class loading and its JIT's warm-up once per worker rather
 * than once per run. A run that breaks the JVM (its code calls {@code System.exit}, the JVM runs out of memory or
 * is killed, the run leaves a thread running or runs past its patience) ends as a failed run with the reason, and
 * the next run gets a fresh JVM. Not for several threads at once.
 */
public final class WarmWorker implements HeadlessRuns {
    /** How long a warm JVM gets to end by itself when it is told there are no more runs, ms. */
    private static final long END_GRACE_MS = 10_000;
    private final ChildProcesses children;
    private final String name;
    private ChildProcesses.Child jvm;
    /** The current JVM's answers, then (once its stdout has ended) {@link #GONE}. */
    private BlockingQueue<String> answers;
    private static final String GONE = "";

    /** A worker whose JVMs {@code children} starts (with its JVM options), named {@code name} in messages. */
    public WarmWorker(ChildProcesses children, String name) {
        this.children = children;
        this.name = name;
    }

    @Override
    public Ended run(String run, List<String> args, Path log, long patienceS) throws IOException, InterruptedException {
        String request = RunHost.request(log.toAbsolutePath(), args) + "\n";
        if (jvm == null) {
            start();
        }
        try {
            OutputStream in = jvm.process.getOutputStream();
            in.write(request.getBytes(StandardCharsets.UTF_8));
            in.flush();
        } catch (IOException gone) { // (it died between runs: the run has not begun)
            jvm.process.waitFor();
            start();
            OutputStream in = jvm.process.getOutputStream();
            in.write(request.getBytes(StandardCharsets.UTF_8));
            in.flush();
        }
        String line;
        try {
            line = patienceS > 0 ? answers.poll(patienceS, TimeUnit.SECONDS) : answers.take();
        } catch (InterruptedException e) {
            stop();
            throw e;
        }
        if (line == null) {
            int code = stop();
            return said(log, new Ended(code, "no end within " + patienceS + " s; its warm JVM was stopped"));
        }
        if (line.equals(GONE)) {
            int code = jvm.process.waitFor();
            String last = jvm.lastErrorLines(5_000);
            jvm = null;
            String why = code > 128 && code < 128 + 65 ? "its warm JVM was killed by signal " + (code - 128)
                    + " during the run" : "its warm JVM exited with code " + code + " during the run (System.exit "
                    + "in its code, or a crash; --fresh-jvm-per-run runs each run in a JVM of its own)";
            return said(log, new Ended(code, why + (last.isEmpty() ? "" : ": " + robosim.protocol.Printable.of(last,
                    200))));
        }
        Ended ended = RunHost.parseAnswer(line);
        if (ended.broke() != null) {
            jvm.process.waitFor(END_GRACE_MS, TimeUnit.MILLISECONDS); // (it exits after saying so)
            stop();
        }
        return ended;
    }

    /** Starts a fresh JVM, its answers into a queue of its own. */
    private void start() throws IOException {
        BlockingQueue<String> queue = new LinkedBlockingQueue<>();
        jvm = children.startWorker(name, RunHost.class.getName(), line -> {
            if (RunHost.parseAnswer(line) != null) { // (anything else the JVM itself printed: not an answer)
                queue.add(line);
            }
        }, () -> queue.add(GONE));
        answers = queue;
    }

    /** Stops the current JVM at once; its exit code. */
    private int stop() throws InterruptedException {
        if (jvm == null) {
            return -1;
        }
        jvm.process.descendants().forEach(ProcessHandle::destroyForcibly);
        jvm.process.destroyForcibly();
        int code = jvm.process.waitFor();
        jvm = null;
        return code;
    }

    /** {@code ended}, its reason written at the end of the run's log too (where the run's own lines are). */
    private static Ended said(Path log, Ended ended) {
        try {
            Files.writeString(log, "warm JVM: " + ended.broke() + "\n", StandardCharsets.UTF_8,
                    StandardOpenOption.CREATE, StandardOpenOption.APPEND);
        } catch (IOException e) {
            // the row says it still
        }
        return ended;
    }

    /** No more runs: the JVM is told (the end of its stdin) and ends by itself, else it is stopped. */
    @Override
    public void close() {
        if (jvm == null) {
            return;
        }
        try {
            jvm.process.getOutputStream().close();
            if (!jvm.process.waitFor(END_GRACE_MS, TimeUnit.MILLISECONDS)) {
                stop();
            }
        } catch (IOException e) {
            jvm.process.destroyForcibly();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            jvm.process.destroyForcibly();
        }
        jvm = null;
    }
}
