package robosim.sweep;

import java.io.IOException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import robosim.runner.ChildProcesses;
import robosim.runner.HeadlessRuns;
import robosim.runner.WarmWorker;

/**
 * A sweep's runs on this machine: a bounded pool of {@code jobs} threads ({@code sweep-run[k]}), each running one
 * run at a time in a warm JVM of its own ({@link WarmWorker}; with {@code --fresh-jvm-per-run}, each run in a new
 * process). A one-JVM run keeps about one core busy. Ctrl-C (any signal that stops
 * this JVM) stops every run at once (thread {@code sweep-stop}); the rows written stay, and the tables are made
 * from them. When the first {@code giveUpAfter} runs to end all failed for one reason (a class path not given, a
 * parameter that is no number), the sweep stops there, says why, and removes their rows (so {@code --resume} runs
 * them once it is mended) rather than failing every run the same way.
 */
final class LocalPool {
    /** How long the stop waits for the runs' threads to see their processes gone, ms. */
    private static final long STOP_WAIT_MS = 15_000;
    private final Sweep sweep;
    private final OutputDirectory out;
    private final int jobs;
    private final boolean keepRecordings;
    private final boolean freshJvmPerRun;
    private final PrintStream err;
    private final int giveUpAfter;
    private volatile boolean stopping;
    private final AtomicInteger unfinished = new AtomicInteger();
    /** The first runs to end, up to {@code giveUpAfter} (guarded by {@code this}). */
    private final List<Row> first = new ArrayList<>();
    /** Every row this pool wrote (guarded by {@code this}): a give-up removes those of its reason. */
    private final List<Row> written = new ArrayList<>();
    /** The reason every one of the first runs failed for, once they all did (then the sweep stops). */
    private volatile String gaveUp;

    /** {@code giveUpAfter}: 0 never gives up. */
    LocalPool(Sweep sweep, OutputDirectory out, int jobs, boolean keepRecordings, boolean freshJvmPerRun,
            int giveUpAfter, PrintStream err) {
        this.sweep = sweep;
        this.out = out;
        this.jobs = jobs;
        this.keepRecordings = keepRecordings;
        this.freshJvmPerRun = freshJvmPerRun;
        this.giveUpAfter = giveUpAfter;
        this.err = err;
    }

    /** Runs {@code todo}; returns the runs that were stopped by a signal from outside (they have no row). */
    int run(List<Integer> todo, Progress progress) throws InterruptedException, IOException {
        ChildProcesses children = new ChildProcesses(sweep.jvmOptions());
        SweepRun runner = new SweepRun(sweep, out, keepRecordings, () -> stopping || children.closing(),
                line -> progress.say(line));
        AtomicInteger next = new AtomicInteger();
        List<Thread> threads = new ArrayList<>();
        for (int k = 0; k < Math.min(jobs, todo.size()); k++) {
            String worker = "worker " + k;
            threads.add(new Thread(() -> {
                try (HeadlessRuns runs = freshJvmPerRun ? HeadlessRuns.freshJvms(children)
                        : new WarmWorker(children, worker)) {
                    runAll(todo, next, runner, runs, children, progress);
                }
            }, "sweep-run[" + k + "]"));
        }
        Thread stop = new Thread(() -> {
            stopping = true;
            children.close();
            joinAll(threads, STOP_WAIT_MS);
            progress.close();
            try {
                int rows = Gather.tablesWithoutPlots(sweep, out);
                err.println("sweep: stopped: " + rows + " of " + sweep.runs() + " runs have rows (" + out.path()
                        + ": runs.csv and summary.csv; sweep.sh gather DIR draws the plots); --resume runs the rest");
            } catch (IOException | RuntimeException e) {
                err.println("sweep: stopped; the tables could not be made: " + e.getMessage());
            }
        }, "sweep-stop");
        Runtime.getRuntime().addShutdownHook(stop);
        threads.forEach(Thread::start);
        for (Thread t : threads) {
            t.join();
        }
        try {
            Runtime.getRuntime().removeShutdownHook(stop);
        } catch (IllegalStateException shuttingDown) {
            Thread.currentThread().join(); // (the stop hook makes the tables; the JVM ends when it is done)
        }
        children.close();
        if (gaveUp != null) {
            int removed = 0;
            synchronized (this) {
                for (Row r : written) { // (the first runs, and any that ended with them for the same reason)
                    if (gaveUp.equals(r.values().get("error")) && java.nio.file.Files.deleteIfExists(out.row(r.index()))) {
                        removed++;
                    }
                }
            }
            progress.close();
            err.println("sweep: the first " + first.size() + " runs all failed: " + gaveUp + "; stopped before the "
                    + "others, the rows of the " + removed + " that failed so removed (mend it, then the same command with "
                    + "--resume runs every run; --give-up-after 0 runs them all anyway)");
            return unfinished.get() + (int) (sweep.runs() - out.rowsWritten().size());
        }
        return unfinished.get();
    }

    /** Keeps {@code row} if it is one of the first to end; gives the sweep up when they all failed alike. */
    private void firstRuns(Row row, ChildProcesses children) {
        synchronized (this) {
            written.add(row);
            if (giveUpAfter == 0 || first.size() >= giveUpAfter || stopping) {
                return;
            }
            first.add(row);
            if (first.size() < giveUpAfter || first.stream().anyMatch(Row::ok)
                    || first.stream().map(r -> r.values().get("error")).distinct().count() > 1) {
                return;
            }
            gaveUp = row.values().get("error");
        }
        stopping = true;
        children.close();
    }

    /** A pool thread's work: the runs of {@code todo} it takes, one after another, until none is left or the stop. */
    private void runAll(List<Integer> todo, AtomicInteger next, SweepRun runner, HeadlessRuns runs,
            ChildProcesses children, Progress progress) {
        int i;
        while (!stopping && !children.closing() && (i = next.getAndIncrement()) < todo.size()) {
            int index = todo.get(i);
            try {
                Row row = runner.run(index, runs);
                if (row != null) {
                    firstRuns(row, children); // (before the stop's check: a row written as the sweep gave up counts)
                }
                if (stopping || children.closing()) {
                    return; // (this JVM is stopping: the run was stopped with it)
                }
                if (row == null) {
                    unfinished.incrementAndGet();
                } else {
                    progress.finished(row.ok());
                }
            } catch (IOException | RuntimeException e) {
                if (stopping || children.closing()) {
                    return; // (started as the stop came: stopped at once, nothing to say)
                }
                err.println("sweep: run " + index + ": " + e.getMessage());
                unfinished.incrementAndGet();
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private static void joinAll(List<Thread> threads, long ms) {
        long deadline = System.nanoTime() + ms * 1_000_000;
        for (Thread t : threads) {
            try {
                t.join(Math.max(1, (deadline - System.nanoTime()) / 1_000_000));
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
