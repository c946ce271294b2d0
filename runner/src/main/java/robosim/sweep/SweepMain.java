package robosim.sweep;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.protocol.CommandLines;
import robosim.runner.ChildProcesses;

/**
 * {@code scripts/sweep.sh SPEC}: runs every run of a sweep file and writes its tables and plots
 * ({@code docs/EXPERIMENTS.md}); {@code status DIR}, {@code task DIR INDEX} (one Slurm task) and {@code gather DIR}
 * (the tables again from the rows) work on an output directory.
 */
@Command(name = "sweep.sh", mixinStandardHelpOptions = true,
        subcommands = {SweepMain.Status.class, SweepMain.Task.class, SweepMain.GatherRows.class},
        description = {"Runs a seed and parameter sweep (a <sweep> file, docs/EXPERIMENTS.md): every combination of "
                + "the parameters' values with every seed, on this machine (a pool of warm JVMs as large as its cores, each "
                + "running one run after another) or, with --slurm, as a Slurm job array (chunks of runs, each in one "
                + "warm JVM). Writes runs.csv (a row per run), summary.csv "
                + "(mean, sd and 95%% confidence interval per combination) and a PNG plot per metric and varied "
                + "parameter into --out.",
                "Exit: 0 every run succeeded; 1 some failed (their rows say why), were stopped, or a metric the file names was "
                        + "never reported; 2 bad input; "
                        + "130 stopped by Ctrl-C, 143 by SIGTERM (the rows written stay: --resume runs the rest)."})
public final class SweepMain implements Callable<Integer> {
    /** Exit code of a sweep some of whose runs failed or left no row. */
    static final int EXIT_RUNS_FAILED = 1;
    /** How long --wait goes on asking squeue when it fails, ns. */
    private static final long SQUEUE_PATIENCE_NS = 120_000_000_000L;
    static final int EXIT_BAD_INPUT = 2;

    @Parameters(index = "0", arity = "0..1", paramLabel = "SPEC.xml", description = "The sweep file.")
    Path spec;

    @Option(names = "--out", paramLabel = "DIR", description = "The output directory: new or empty, or this sweep's "
            + "with --resume (default: sweep-NAME-DATE-TIME here). On a cluster: on the file system every node shares.")
    Path out;

    @Option(names = "--resume", description = "Run only the runs that have no row in --out yet.")
    boolean resume;

    @Mixin
    WorkerOptions workers;

    @Option(names = "--give-up-after", paramLabel = "K", description = "On this machine: when the first K runs to end "
            + "all failed for one reason, stop there, say why and remove their rows (default: 3; 0: run every run "
            + "whatever happens).")
    Integer giveUpAfter;

    @Option(names = "--jobs", paramLabel = "N", description = "Runs at once on this machine (default: its cores, "
            + "${sys:robosim.cores}).")
    Integer jobs;

    @Option(names = "--slurm", description = "Submit the runs as a Slurm job array and a gather job that makes the "
            + "tables (sbatch); sweep.sh status DIR shows how far it is.")
    boolean slurm;

    @Option(names = "--partition", paramLabel = "NAME", description = "With --slurm: the partition (default: the "
            + "cluster's).")
    String partition;

    @Option(names = "--time", paramLabel = "LIMIT", description = "With --slurm: each task's time limit, as sbatch "
            + "--time takes it (default: the partition's).")
    String time;

    @Option(names = "--max-parallel", paramLabel = "K", defaultValue = "100", description = "With --slurm: tasks "
            + "running at once (the array's %%K; default: ${DEFAULT-VALUE}).")
    int maxParallel;

    @Option(names = "--runs-per-task", paramLabel = "K", description = "With --slurm: runs each task runs, one after "
            + "another in one warm JVM (default: as many as make about 30 s of work, from the world's robots and the "
            + "steps; 1: a task per run).")
    Integer runsPerTask;

    @Option(names = "--wait", description = "With --slurm: wait until the gather job has ended, showing progress (squeue "
            + "twice a second), then exit as a local sweep does.")
    boolean await;

    @Override
    public Integer call() throws Exception {
        if (spec == null) {
            return bad("sweep: a sweep file is needed (sweep.sh SPEC.xml, or status/task/gather DIR; see --help)");
        }
        if (!slurm && (partition != null || time != null || await || runsPerTask != null)) {
            return bad("sweep: --partition, --time, --runs-per-task and --wait go with --slurm");
        }
        if (runsPerTask != null && runsPerTask < 1) {
            return bad("sweep: --runs-per-task must be >= 1, got " + runsPerTask);
        }
        if (slurm && giveUpAfter != null) {
            return bad("sweep: --give-up-after is for this machine's pool (a Slurm sweep's tasks run apart)");
        }
        if (giveUpAfter != null && giveUpAfter < 0) {
            return bad("sweep: --give-up-after must be >= 0 (0: never), got " + giveUpAfter);
        }
        if ((jobs != null && jobs < 1) || maxParallel < 1) {
            return bad("sweep: --jobs and --max-parallel must be >= 1");
        }
        if (slurm && jobs != null) {
            return bad("sweep: --jobs is for this machine's pool; with --slurm, --max-parallel");
        }
        Sweep sweep;
        OutputDirectory dir;
        try {
            sweep = SweepFile.read(spec);
            dir = new OutputDirectory(out != null ? out : Path.of("sweep-" + name(spec) + "-"
                    + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss"))));
        } catch (SweepException e) {
            return bad(e.getMessage());
        }
        java.io.Closeable lock = null;
        try {
            // (a sweep's directory is held before it is prepared: --resume may renumber its rows, growing it)
            lock = dir.isSweep() ? held(dir) : null;
            dir.prepare(sweep, resume);
            lock = lock != null ? lock : held(dir);
        } catch (SweepException e) {
            if (lock != null) {
                lock.close();
            }
            return bad(e.getMessage());
        }
        try (java.io.Closeable held = lock) { // (held while submitting, or while the local pool runs)
            return slurm ? slurm(sweep, dir, dir.missing(sweep), System.err)
                    : local(sweep, dir, dir.missing(sweep), System.err);
        }
    }

    /** {@code dir} held for this sweep ({@link OutputDirectory#lock}), unless Slurm jobs of it still run. */
    private static java.io.Closeable held(OutputDirectory dir) throws SweepException, IOException,
            InterruptedException {
        java.io.Closeable lock = dir.lock();
        Slurm.Jobs earlier = Slurm.jobs(dir);
        if (earlier != null && Slurm.stillActive(earlier)) {
            lock.close();
            throw new SweepException(dir.path() + ": its Slurm jobs (" + earlier.all() + ") are still running their "
                    + "runs: wait for them (sweep.sh status " + dir.path() + ") or scancel them first");
        }
        return lock;
    }

    private int local(Sweep sweep, OutputDirectory dir, List<Integer> todo, PrintStream err) throws Exception {
        say(sweep, dir, todo, err);
        int cores = Runtime.getRuntime().availableProcessors();
        Progress progress = new Progress(todo.size(), err, System.console() != null);
        int unfinished = new LocalPool(sweep, dir, jobs != null ? jobs : cores, workers.keepRecordings,
                workers.freshJvmPerRun, giveUpAfter == null ? 3 : giveUpAfter, err).run(todo, progress);
        return finish(sweep, dir, unfinished, err);
    }

    /** The sweep's first line: how many runs, how many to run, where. */
    private static void say(Sweep sweep, OutputDirectory dir, List<Integer> todo, PrintStream err) {
        err.println("sweep: " + sweep.runs() + " runs (" + sweep.combinationCount() + " combinations x " + sweep.seeds()
                + " seeds" + (sweep.repeat() > 1 ? " x " + sweep.repeat() : "") + ", " + sweep.steps() + " steps, "
                + sweep.layout().written() + "), " + todo.size() + " to run, into " + dir.path());
    }

    private int slurm(Sweep sweep, OutputDirectory dir, List<Integer> todo, PrintStream err) throws Exception {
        say(sweep, dir, todo, err);
        if (todo.isEmpty()) {
            Gather.tables(sweep, dir);
            err.println("sweep: every run has its row: nothing submitted; tables made");
            return finish(sweep, dir, 0, err);
        }
        String script = System.getenv("ROBOSIM_SWEEP_SCRIPT");
        if (script == null) {
            return bad("sweep: --slurm is started by scripts/sweep.sh (ROBOSIM_SWEEP_SCRIPT names it for the tasks)");
        }
        Slurm.Submitted submitted;
        try {
            submitted = Slurm.submit(sweep, dir, todo, new Slurm.Options(partition, time, maxParallel,
                    workers.keepRecordings, runsPerTask == null ? 0 : runsPerTask, workers.freshJvmPerRun),
                    Path.of(script));
        } catch (SweepException e) {
            return bad(e.getMessage());
        }
        Slurm.Jobs jobsSubmitted = submitted.jobs();
        err.println("sweep: submitted job array " + String.join(", ", jobsSubmitted.arrays()) + " (" + submitted.tasks()
                + (submitted.tasks() == 1 ? " task" : " tasks") + " of up to " + submitted.runsPerTask()
                + (submitted.runsPerTask() == 1 ? " run" : " runs") + ", at most " + maxParallel
                + " at once) and gather job "
                + jobsSubmitted.gather() + " (after it); "
                + "sweep.sh status " + dir.path());
        if (!await) {
            return 0;
        }
        Progress progress = new Progress(todo.size(), err, System.console() != null);
        java.util.BitSet asked = new java.util.BitSet();
        todo.forEach(asked::set);
        java.util.BitSet seen = new java.util.BitSet();
        long squeueFailingSince = 0;
        while (true) {
            boolean active;
            try {
                active = Slurm.active(jobsSubmitted);
                squeueFailingSince = 0;
            } catch (SweepException e) { // (a slow or restarting slurmctld: asked again, for a while)
                squeueFailingSince = squeueFailingSince == 0 ? System.nanoTime() : squeueFailingSince;
                if (System.nanoTime() - squeueFailingSince > SQUEUE_PATIENCE_NS) {
                    progress.close();
                    err.println("sweep: " + e.getMessage() + " for " + SQUEUE_PATIENCE_NS / 1_000_000_000
                            + " s; the jobs go on: sweep.sh status " + dir.path());
                    return EXIT_RUNS_FAILED;
                }
                active = true;
            }
            for (Row r : dir.rowsWritten()) {
                if (asked.get(r.index()) && !seen.get(r.index())) {
                    seen.set(r.index());
                    progress.finished(r.ok());
                }
            }
            if (!active) {
                break;
            }
            Thread.sleep(500); // (polling squeue: Slurm tells no one when a job ends)
        }
        progress.close();
        return finish(sweep, dir, todo.size() - seen.cardinality(), err);
    }

    /** The sweep's end: tables made (again), one line, and the exit code. */
    private static int finish(Sweep sweep, OutputDirectory dir, int unfinished, PrintStream err) throws IOException {
        int rows = Gather.tables(sweep, dir);
        java.nio.file.Path text = dir.path().resolve("summary.txt");
        if (java.nio.file.Files.isRegularFile(text)) {
            System.out.print(java.nio.file.Files.readString(text));
            System.out.flush();
        }
        long failed = dir.rowsWritten().stream().filter(r -> !r.ok()).count();
        long missing = sweep.runs() - rows;
        List<String> unreported = unreported(sweep, dir.rowsWritten());
        for (String name : unreported) {
            err.println("sweep: no robot reported '" + name + "' in any run (<metric report=\"" + name + "\"> in "
                    + sweep.file().getFileName() + "; a name the control code does not report?): its column is empty");
        }
        err.println("sweep: " + rows + " of " + sweep.runs() + " runs have rows, " + failed + " failed"
                + (missing > 0 ? ", " + missing + " without a row (--resume runs them)" : "")
                + (unreported.isEmpty() ? "" : ", " + unreported.size() + " metric(s) never reported")
                + "; tables and plots in " + dir.path());
        return failed > 0 || missing > 0 || unfinished > 0 || !unreported.isEmpty() ? EXIT_RUNS_FAILED : 0;
    }

    /** The reports the sweep file names that no robot made in any run that succeeded (none when no run did). */
    static List<String> unreported(Sweep sweep, List<Row> rows) {
        List<Row> ok = rows.stream().filter(Row::ok).toList();
        List<String> out = new java.util.ArrayList<>();
        if (ok.isEmpty()) {
            return out;
        }
        for (MetricChoice c : sweep.metrics()) {
            if (c.kind() == MetricChoice.Kind.REPORT && ok.stream().noneMatch(r -> r.values().keySet().stream()
                    .anyMatch(column -> c.equals(sweep.owner(column))))) {
                out.add(c.name());
            }
        }
        return out;
    }

    private static String name(Path spec) {
        String n = spec.getFileName().toString();
        return n.endsWith(".xml") ? n.substring(0, n.length() - 4) : n;
    }

    static int bad(String line) {
        System.err.println(line);
        return EXIT_BAD_INPUT;
    }

    /** {@code sweep.sh status DIR}: rows written, and the Slurm jobs' states. */
    @Command(name = "status", mixinStandardHelpOptions = true, description = "Shows how far the sweep in DIR is: rows "
            + "written and failed, and, for a Slurm sweep, its jobs' tasks by state (squeue).")
    static final class Status implements Callable<Integer> {
        @Parameters(paramLabel = "DIR", description = "The sweep's output directory.")
        Path dir;

        @Override
        public Integer call() throws Exception {
            OutputDirectory out = new OutputDirectory(dir);
            Sweep sweep;
            try {
                sweep = out.sweep();
            } catch (SweepException e) {
                return bad(e.getMessage());
            }
            List<Row> rows = out.rowsWritten();
            long failed = rows.stream().filter(r -> !r.ok()).count();
            System.out.println(out.path() + ": " + rows.size() + " of " + sweep.runs() + " runs have rows, " + failed
                    + " failed" + (java.nio.file.Files.exists(out.path().resolve("runs.csv")) ? "; runs.csv written" : ""));
            Slurm.Jobs jobs = Slurm.jobs(out);
            if (jobs != null) {
                try {
                    Map<String, Integer> states = Slurm.states(jobs);
                    System.out.println("slurm: array " + String.join(", ", jobs.arrays()) + ", gather " + jobs.gather() + ": "
                            + (states.isEmpty()
                            ? "no longer shown by squeue (ended)" : states.toString().replaceAll("[{}]", "")));
                } catch (SweepException e) {
                    System.out.println("slurm: " + e.getMessage());
                }
            }
            return 0;
        }
    }

    /** {@code sweep.sh task DIR INDEX|--runs LIST}: runs of the sweep in DIR, as a Slurm task runs its chunk. */
    @Command(name = "task", mixinStandardHelpOptions = true, description = "Runs run INDEX, or the runs of --runs, of "
            + "the sweep in DIR, one after another in one warm JVM, and writes their rows (what each task of a Slurm "
            + "sweep's array does); a run that has its row already is not run again.")
    static final class Task implements Callable<Integer> {
        @Parameters(index = "0", paramLabel = "DIR", description = "The sweep's output directory.")
        Path dir;

        @Parameters(index = "1", arity = "0..1", paramLabel = "INDEX", description = "The run (from 0).")
        Integer index;

        @Option(names = "--runs", paramLabel = "LIST", description = "The runs, as 0-9,12,15-20.")
        String runs;

        @Mixin
        WorkerOptions workers;

        @Override
        public Integer call() throws Exception {
            OutputDirectory out = new OutputDirectory(dir);
            Sweep sweep;
            List<Integer> todo;
            try {
                sweep = out.sweep();
                if ((index == null) == (runs == null)) {
                    return bad("sweep: task takes a run's INDEX or --runs LIST, one of them");
                }
                todo = index != null ? List.of(index) : indices(runs, sweep.runs());
                if (index != null && (index < 0 || index >= sweep.runs())) {
                    return bad("sweep: run " + index + " is not one of the " + sweep.runs() + " runs of "
                            + sweep.file());
                }
            } catch (SweepException e) {
                return bad(e.getMessage());
            }
            java.util.concurrent.atomic.AtomicBoolean stopping = new java.util.concurrent.atomic.AtomicBoolean();
            // (Slurm ends a task past its time with SIGTERM: the run then under way writes no row, nor any after it)
            Runtime.getRuntime().addShutdownHook(new Thread(() -> stopping.set(true), "sweep-stop"));
            SweepRun sweepRun = new SweepRun(sweep, out, workers.keepRecordings, stopping::get, System.err::println);
            int unfinished = 0;
            try (ChildProcesses children = new ChildProcesses(sweep.jvmOptions());
                 robosim.runner.HeadlessRuns where = workers.freshJvmPerRun ? robosim.runner.HeadlessRuns.freshJvms(children)
                         : new robosim.runner.WarmWorker(children, "worker")) {
                for (int i : todo) {
                    if (java.nio.file.Files.exists(out.row(i))) {
                        System.err.println("sweep: run " + i + " has its row already");
                        continue;
                    }
                    Row row;
                    try {
                        row = stopping.get() ? null : sweepRun.run(i, where);
                    } catch (java.io.IOException | RuntimeException e) { // (this run's: the chunk's others go on)
                        System.err.println("sweep: run " + i + ": " + e.getMessage());
                        unfinished++;
                        continue;
                    }
                    System.err.println("sweep: run " + i + ": " + (row == null ? "stopped, no row"
                            : row.values().get("status")));
                    unfinished += row == null ? 1 : 0;
                }
            }
            return unfinished > 0 ? EXIT_RUNS_FAILED : 0;
        }

        /** The runs of a list such as {@code 0-9,12,15-20}, each one of a sweep's {@code runs}. */
        static List<Integer> indices(String list, long runs) throws SweepException {
            List<Integer> out = new java.util.ArrayList<>();
            for (String part : list.split(",", -1)) {
                java.util.regex.Matcher m = java.util.regex.Pattern.compile("([0-9]{1,9})(?:-([0-9]{1,9}))?")
                        .matcher(part.trim());
                if (!m.matches()) {
                    throw new SweepException("sweep: --runs " + robosim.protocol.Printable.of(list, 100)
                            + ": not a list of runs such as 0-9,12,15-20");
                }
                int from = Integer.parseInt(m.group(1));
                int to = m.group(2) == null ? from : Integer.parseInt(m.group(2));
                if (to < from) {
                    throw new SweepException("sweep: --runs: " + part.trim() + " is not a range from low to high");
                }
                if (to >= runs) {
                    throw new SweepException("sweep: --runs: run " + to + " is not one of the sweep's " + runs
                            + " runs");
                }
                for (int i = from; i <= to; i++) {
                    out.add(i);
                }
            }
            return out;
        }
    }

    /** {@code sweep.sh gather DIR}: the tables and plots from the rows written. */
    @Command(name = "gather", mixinStandardHelpOptions = true, description = "Makes runs.csv, summary.csv and the plots "
            + "of the sweep in DIR from the rows written so far (a Slurm sweep's gather job does this).")
    static final class GatherRows implements Callable<Integer> {
        @Parameters(paramLabel = "DIR", description = "The sweep's output directory.")
        Path dir;

        @Override
        public Integer call() throws Exception {
            OutputDirectory out = new OutputDirectory(dir);
            try {
                return finish(out.sweep(), out, 0, System.err);
            } catch (SweepException e) {
                return bad(e.getMessage());
            }
        }
    }

    public static void main(String[] args) {
        System.setProperty("robosim.cores", Integer.toString(Runtime.getRuntime().availableProcessors()));
        System.exit(commandLine().execute(args));
    }

    /** sweep.sh's command line: a bad option or a failure is one line, not a stack trace. */
    static CommandLine commandLine() {
        CommandLine cl = CommandLines.of("sweep", new SweepMain());
        cl.setExecutionExceptionHandler((ex, c, parsed) -> {
            System.err.println("sweep: " + (ex instanceof java.nio.file.AccessDeniedException ? "permission denied: "
                    : ex instanceof java.nio.file.NoSuchFileException ? "no such file: " : "") + ex.getMessage());
            return EXIT_RUNS_FAILED;
        });
        return cl;
    }
}
