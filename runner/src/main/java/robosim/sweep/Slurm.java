package robosim.sweep;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;

/**
 * A sweep on a Slurm cluster: one {@code sbatch} job array whose tasks run the runs still missing in chunks
 * ({@code %K} tasks at once), each task running its chunk one run after another in one warm JVM
 * ({@code sweep.sh task DIR --runs LIST}), so that a task's start (its JVMs, Slurm's own cost) is paid once a chunk;
 * and a gather job that waits for the whole array
 * ({@code --dependency=afterany}: a failed task is a row, and {@code afterok} would wait for ever) and makes the
 * tables and plots. The jobs' ids go into {@code DIR/slurm/jobs}; {@code sweep.sh status DIR} reads them. Every
 * Slurm command has a deadline and its output is bounded.
 */
final class Slurm {
    /** How long one Slurm command may take, ms. */
    private static final long COMMAND_MS = 60_000;
    /** The most output of one Slurm command read, bytes. */
    private static final int MAX_OUTPUT = 1 << 20;
    /** Job states of a job that has not ended. */
    private static final List<String> ACTIVE = List.of("PENDING", "RUNNING", "CONFIGURING", "COMPLETING",
            "SUSPENDED", "REQUEUED", "REQUEUE_FED", "REQUEUE_HOLD", "RESIZING", "SIGNALING", "STAGE_OUT", "STOPPED",
            "RESV_DEL_HOLD", "SPECIAL_EXIT");

    /**
     * Where and how long: {@code --partition}, {@code --time} (null: the cluster's defaults), {@code --max-parallel};
     * and whether the tasks keep their recordings.
     */
    record Options(String partition, String time, int maxParallel, boolean keepRecordings, int runsPerTask,
            boolean freshJvmPerRun) {
    }

    /** How long a task is meant to last, by default (a chunk of runs of about this much), s. */
    static final double TASK_S = 30;
    /** What a run is taken to cost before it is measured: a warm one-JVM run's robot-steps a second, on one core. */
    private static final double ROBOT_STEPS_PER_S = 50_000;

    /** The submitted jobs: the arrays' ids (one, unless the sweep is larger than MaxArraySize) and the gather job's. */
    record Jobs(List<String> arrays, String gather) {
        /** Every job id, comma-separated, as squeue -j takes them. */
        String all() {
            List<String> ids = new ArrayList<>(arrays);
            if (gather != null) {
                ids.add(gather);
            }
            return String.join(",", ids);
        }
    }

    /** What was submitted: the jobs, the array's tasks and the runs each task runs (the last may run fewer). */
    record Submitted(Jobs jobs, int tasks, int runsPerTask) {
    }

    /** Slurm's MaxArraySize when the cluster does not say. */
    private static final int DEFAULT_MAX_ARRAY_SIZE = 1001;

    private Slurm() {
    }

    /**
     * Submits the runs {@code todo} of the sweep in {@code out} and its gather job; {@code script} is sweep.sh. A
     * sweep of more runs than the cluster's {@code MaxArraySize} takes several arrays, each of indices from 0 with
     * an offset; the gather job waits for all of them.
     */
    static Submitted submit(Sweep sweep, OutputDirectory out, List<Integer> todo, Options options, Path script)
            throws IOException, SweepException, InterruptedException {
        int perTask = options.runsPerTask() > 0 ? options.runsPerTask() : runsPerTask(sweep);
        List<String> chunks = new ArrayList<>();
        for (int from = 0; from < todo.size(); from += perTask) {
            chunks.add(ranges(todo.subList(from, Math.min(todo.size(), from + perTask))));
        }
        String where = out.path().toString();
        if (!where.chars().allMatch(c -> c >= ' ' && c != '%' && c != 127)) {
            throw new SweepException("sweep: --out " + robosim.protocol.Printable.of(where, 200) + ": a directory for "
                    + "Slurm may hold no control character and no '%' (sbatch reads it as a pattern)");
        }
        Path dir = out.slurm();
        Files.createDirectories(dir);
        Path task = taskScript(dir);
        Path written = dir.resolve(".task.sh.tmp-" + ProcessHandle.current().pid());
        Files.writeString(written, "#!/usr/bin/env bash\n# A chunk of runs of the sweep in its directory per task of the "
                + "array (written by sweep.sh --slurm): chunk OFFSET + the task's index\n"
                + "export ROBOSIM_NO_BUILD=1 # (every task runs the build the submission made: none builds)\n"
                + "chunks=(" + String.join(" ", chunks) + ")\n"
                + "exec " + quoted(script.toString()) + " task " + quoted(where)
                + " --runs \"${chunks[$(($1 + SLURM_ARRAY_TASK_ID))]}\""
                + (options.keepRecordings() ? " --keep-recordings" : "")
                + (options.freshJvmPerRun() ? " --fresh-jvm-per-run" : "") + "\n", StandardCharsets.UTF_8);
        Files.setPosixFilePermissions(written, PosixFilePermissions.fromString("rwxr-xr-x"));
        // (a script of its own: a pending task of an earlier submission still runs that one's chunks)
        Files.move(written, task, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        List<String> place = new ArrayList<>();
        if (options.partition() != null) {
            place.add("--partition=" + options.partition());
        }
        if (options.time() != null) {
            place.add("--time=" + options.time());
        }
        Path jobs = dir.resolve("jobs");
        Files.deleteIfExists(jobs);
        List<String> arrays = new ArrayList<>();
        List<Integer> tasks = java.util.stream.IntStream.range(0, chunks.size()).boxed().toList();
        for (Map.Entry<Integer, String> a : arrays(tasks, maxArraySize()).entrySet()) {
            List<String> array = new ArrayList<>(List.of("sbatch", "--parsable", "--job-name=robosim-sweep",
                    "--array=" + a.getValue() + "%" + options.maxParallel(), "--output=" + dir.resolve("task-%A_%a.out"),
                    "--cpus-per-task=" + (sweep.layout() == Sweep.Layout.ONE_JVM ? 1 : 2)));
            array.addAll(place);
            array.addAll(List.of(task.toString(), Integer.toString(a.getKey())));
            String id = jobId(run(array));
            arrays.add(id);
            Files.writeString(jobs, "array " + id + "\n", StandardCharsets.UTF_8, java.nio.file.StandardOpenOption.CREATE,
                    java.nio.file.StandardOpenOption.APPEND); // (at once: a later failure leaves it known)
        }
        List<String> gather = new ArrayList<>(List.of("sbatch", "--parsable", "--job-name=robosim-sweep-gather",
                "--dependency=afterany:" + String.join(":", arrays), "--output=" + dir.resolve("gather.out")));
        gather.addAll(place);
        gather.add("--wrap=export ROBOSIM_NO_BUILD=1; exec " + quoted(script.toString()) + " gather " + quoted(where));
        String gatherId = jobId(run(gather));
        Files.writeString(jobs, "gather " + gatherId + "\n", StandardCharsets.UTF_8, java.nio.file.StandardOpenOption.APPEND);
        return new Submitted(new Jobs(arrays, gatherId), chunks.size(), perTask);
    }

    /** This submission's task script: {@code task-N.sh}, N one more than any earlier submission's. */
    private static Path taskScript(Path dir) throws IOException {
        int n = 1;
        while (Files.exists(dir.resolve("task-" + n + ".sh"))) {
            n++;
        }
        return dir.resolve("task-" + n + ".sh");
    }

    /**
     * Runs a task does by default: as many as make about {@link #TASK_S} of work, from the world's robots and the
     * steps (a run of processes counts its JVMs' start too); at least one.
     */
    static int runsPerTask(Sweep sweep) {
        int robots;
        try {
            robots = new robosim.environment.config.EnvironmentLoader().load(sweep.world()).robots().size();
        } catch (robosim.environment.config.EnvironmentFileException | RuntimeException e) {
            return 1; // (its runs will say what is wrong, each)
        }
        double runS = (sweep.layout() == Sweep.Layout.ONE_JVM ? 0.1 : 1.5)
                + sweep.steps() * (double) Math.max(1, robots) / ROBOT_STEPS_PER_S;
        return (int) Math.max(1, Math.min(Integer.MAX_VALUE / 2, Math.ceil(TASK_S / runS)));
    }

    /** The cluster's largest array index + 1 ({@code scontrol show config}: MaxArraySize); Slurm's default when unsaid. */
    private static int maxArraySize() throws IOException, SweepException, InterruptedException {
        for (String line : run(List.of("scontrol", "show", "config")).split("\n")) {
            String[] kv = line.split("=", 2);
            if (kv.length == 2 && kv[0].trim().equals("MaxArraySize") && kv[1].trim().matches("[0-9]{1,9}")) {
                return Math.max(1, Integer.parseInt(kv[1].trim()));
            }
        }
        return DEFAULT_MAX_ARRAY_SIZE;
    }

    /** The jobs submitted for {@code out}, or null if none were. */
    static Jobs jobs(OutputDirectory out) throws IOException {
        Path file = out.slurm().resolve("jobs");
        if (!Files.exists(file)) {
            return null;
        }
        List<String> arrays = new ArrayList<>();
        String gather = null;
        for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
            String[] kv = line.trim().split(" ");
            if (kv.length == 2 && kv[1].matches("[0-9]{1,12}")) {
                if (kv[0].equals("array")) {
                    arrays.add(kv[1]);
                } else if (kv[0].equals("gather")) {
                    gather = kv[1];
                }
            }
        }
        return new Jobs(arrays, gather);
    }

    /**
     * True while any of the jobs has not ended, as far as this machine can tell: false where there is no
     * {@code squeue} (the directory was made on a cluster and is resumed elsewhere) or Slurm has forgotten them.
     */
    static boolean stillActive(Jobs jobs) throws IOException, InterruptedException {
        try {
            return active(jobs);
        } catch (SweepException noSqueueOrForgotten) {
            return false;
        }
    }

    /** True while any of the jobs (any task of the array) has not ended, as {@code squeue} says. */
    static boolean active(Jobs jobs) throws IOException, SweepException, InterruptedException {
        for (String state : run(List.of("squeue", "-h", "-r", "-t", "all", "-j", jobs.all(), "-o", "%T")).split("\n")) {
            if (ACTIVE.contains(state.trim())) {
                return true;
            }
        }
        return false;
    }

    /**
     * How many of the jobs' tasks are in each state, as {@code squeue -t all} still shows them (none once Slurm has
     * forgotten the jobs: it then says their ids are invalid).
     */
    static Map<String, Integer> states(Jobs jobs) throws IOException, SweepException, InterruptedException {
        Map<String, Integer> count = new TreeMap<>();
        String shown;
        try {
            shown = run(List.of("squeue", "-h", "-r", "-t", "all", "-j", jobs.all(), "-o", "%j %T"));
        } catch (SweepException e) {
            if (e.getMessage().contains("Invalid job id")) {
                return count;
            }
            throw e;
        }
        for (String line : shown.split("\n")) {
            if (!line.isBlank()) {
                count.merge(line.trim().replace("robosim-sweep-gather", "gather").replace("robosim-sweep", "run"), 1,
                        Integer::sum);
            }
        }
        return count;
    }

    /**
     * The job arrays for the runs {@code todo} (sorted) when an array's indices must stay under {@code most}
     * (MaxArraySize): each array's offset (a multiple of {@code most}) and its {@code --array} indices, the runs
     * less the offset, in order.
     */
    static Map<Integer, String> arrays(List<Integer> todo, int most) {
        Map<Integer, String> out = new java.util.LinkedHashMap<>();
        for (int from = 0; from < todo.size(); ) {
            int offset = todo.get(from) / most * most;
            List<Integer> chunk = new ArrayList<>();
            while (from < todo.size() && todo.get(from) < offset + most) {
                chunk.add(todo.get(from++) - offset);
            }
            out.put(offset, ranges(chunk));
        }
        return out;
    }

    /** {@code 0-5,7,9-11} for these sorted indices. */
    static String ranges(List<Integer> indices) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < indices.size(); i++) {
            int from = indices.get(i);
            int to = from;
            while (i + 1 < indices.size() && indices.get(i + 1) == to + 1) {
                to = indices.get(++i);
            }
            b.append(b.length() == 0 ? "" : ",").append(from).append(from == to ? "" : "-" + to);
        }
        return b.toString();
    }

    private static String jobId(String parsable) throws SweepException {
        String id = parsable.trim().split(";")[0];
        if (!id.matches("[0-9]{1,12}")) {
            throw new SweepException("sbatch: answered '" + robosim.protocol.Printable.of(parsable.trim(), 100)
                    + "', not a job id");
        }
        return id;
    }

    /** Runs a Slurm command; its output, or one line naming it and what it said when it fails or overruns. */
    private static String run(List<String> command) throws IOException, SweepException, InterruptedException {
        Path output = Files.createTempFile("robosim-slurm", ".out");
        try {
            Process p;
            try {
                p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output.toFile()).start();
            } catch (IOException e) {
                throw new SweepException(command.get(0) + ": not found on this machine (is it a Slurm cluster's node?)");
            }
            if (!p.waitFor(COMMAND_MS, TimeUnit.MILLISECONDS)) {
                p.destroyForcibly();
                throw new SweepException(command.get(0) + ": no answer within " + COMMAND_MS / 1000 + " s");
            }
            String text;
            try (InputStream in = Files.newInputStream(output)) {
                text = new String(in.readNBytes(MAX_OUTPUT), StandardCharsets.UTF_8);
            }
            if (p.exitValue() != 0) {
                throw new SweepException(command.get(0) + " failed (exit " + p.exitValue() + "): "
                        + robosim.protocol.Printable.of(text.strip(), 300));
            }
            return text;
        } finally {
            Files.deleteIfExists(output);
        }
    }

    private static String quoted(String s) {
        return "'" + s.replace("'", "'\\''") + "'";
    }
}
