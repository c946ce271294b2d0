package robosim.sweep;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.Printable;
import robosim.runner.HeadlessRuns;

/**
 * Runs one run of a sweep (the headless runner, in the sweep's layout, recording), in a warm JVM or a fresh one
 * ({@link HeadlessRuns}), and writes its row from the run's summary line and its recording. The same on this
 * machine's pool and in a Slurm task, so both give the same rows but for the wall time. A run stopped (the sweep's Ctrl-C; SIGINT or SIGTERM from anyone,
 * Slurm ending its task) writes no row: {@code --resume} runs it again. One killed by another signal (SIGKILL from
 * the kernel's out-of-memory killer, a crash) is a failed row that says which; so is one that broke its warm JVM
 * ({@link HeadlessRuns.Ended#broke()}).
 */
final class SweepRun {
    /** Exit codes from 128 up are a signal's (128 + its number): the run was stopped, not finished. */
    private static final int SIGNALLED = 128;
    private static final int SIGINT = 2;
    private static final int SIGTERM = 15;
    /** How long past its {@code runTimeoutS} a run's JVM is waited for before it is stopped, s. */
    private static final long PATIENCE_S = 30;
    private final Sweep sweep;
    private final OutputDirectory out;
    private final boolean keepRecordings;
    private final java.util.function.BooleanSupplier stopped;
    private final java.util.function.Consumer<String> console;
    /** What was said on the console already: a reason of failed runs, a report no robot made (each said once). */
    private final java.util.Set<String> said = java.util.concurrent.ConcurrentHashMap.newKeySet();

    /**
     * Runs of {@code sweep} into {@code out}; {@code stopped}: the sweep is being stopped (a run ending then writes no
     * row); {@code console}: where a line for the user goes (a failed run's reason, a report no robot made, each
     * the first time).
     */
    SweepRun(Sweep sweep, OutputDirectory out, boolean keepRecordings, java.util.function.BooleanSupplier stopped,
            java.util.function.Consumer<String> console) {
        this.sweep = sweep;
        this.out = out;
        this.keepRecordings = keepRecordings;
        this.stopped = stopped;
        this.console = console;
    }

    /**
     * Runs run {@code index} where {@code runs} says and writes its row; null when it was stopped by a signal or the
     * sweep's stop (no row).
     */
    Row run(int index, HeadlessRuns runs) throws IOException, InterruptedException {
        Sweep.Run run = sweep.run(index);
        Path recording = out.recording(index);
        Path log = out.log(index);
        Files.deleteIfExists(recording); // (a run stopped before: the runner records only into a new file)
        List<String> args = new ArrayList<>(List.of("--env", sweep.world().toString(), "--steps",
                Long.toString(sweep.steps()), "--seed", Long.toString(run.seed()), "--record", recording.toString(),
                "--output-dir", out.outputs(index).toString()));
        if (sweep.metrics().stream().noneMatch(m -> m.kind() == MetricChoice.Kind.CLASS)) {
            args.add("--record-without-readings"); // (only a metric class of the user's might read them)
        }
        run.parameters().forEach((name, value) -> args.addAll(List.of("--param", name + "=" + value)));
        args.addAll(sweep.layout().options());
        if (sweep.runTimeoutS() > 0) {
            args.addAll(List.of("--timeout-s", Long.toString(sweep.runTimeoutS())));
        }
        long start = System.nanoTime();
        HeadlessRuns.Ended ended = runs.run("run " + index, args, log,
                sweep.runTimeoutS() > 0 ? sweep.runTimeoutS() + PATIENCE_S : 0);
        int code = ended.code();
        double wallS = (System.nanoTime() - start) / 1e9;
        if (stopped.getAsBoolean() || code == SIGNALLED + SIGINT || code == SIGNALLED + SIGTERM) {
            return null;
        }
        Map<String, String> values = new LinkedHashMap<>();
        values.put("index", Integer.toString(index));
        values.put("seed", Long.toString(run.seed()));
        values.put("repetition", Integer.toString(run.repetition()));
        values.putAll(run.parameters());
        robosim.runner.RunLog lines = robosim.runner.RunLog.read(log);
        Map<String, String> summary = lines.summary();
        String error = ended.broke() != null ? ended.broke() : code == 0 ? ""
                : code > SIGNALLED && code < SIGNALLED + 65 ? "killed by signal " + (code - SIGNALLED) : lines.lastError();
        Map<String, Double> metrics = Map.of();
        if (Files.exists(recording)) {
            try {
                RunMetrics.Measured measured = RunMetrics.measure(recording, sweep.metrics(), sweep.areaCellM());
                metrics = measured.values();
                for (String name : code == 0 && error.isEmpty() ? measured.unreported() : List.<String>of()) {
                    if (said.add("unreported " + name)) {
                        console.accept("sweep: run " + index + ": no robot reported '" + name + "' (reported: "
                                + (measured.reported().isEmpty() ? "nothing" : String.join(", ", measured.reported()))
                                + "); its column stays empty");
                    }
                }
            } catch (IOException | RuntimeException e) {
                error = error.isEmpty() ? "metrics: " + e.getMessage() : error;
            }
        } else if (code == 0) {
            error = "no recording";
        }
        values.put("status", code == 0 && error.isEmpty() ? Row.OK : Row.FAILED);
        values.put("exit_code", Integer.toString(code));
        for (String field : List.of("steps", "robots", "messages", "control_failed")) {
            values.put(field, summary.getOrDefault(field, ""));
        }
        for (Map.Entry<String, Double> m : metrics.entrySet()) { // (a name the row has already: a reported one)
            values.put(values.containsKey(m.getKey()) || Row.LAST.contains(m.getKey()) ? "report." + m.getKey()
                    : m.getKey(), Csv.number(m.getValue()));
        }
        // (the output directory named as DIR: the same run's row is the same wherever the sweep writes)
        values.put("error", Printable.of(error.replace(out.path().toString(), "DIR"), 300));
        values.put("wall_s", String.format(java.util.Locale.ROOT, "%.3f", wallS));
        Row row = new Row(values);
        row.write(out.row(index));
        if (!row.ok() && said.add("failed " + values.get("error"))) {
            console.accept("sweep: run " + index + " failed: " + values.get("error"));
        }
        if (!keepRecordings) {
            Files.deleteIfExists(recording);
        }
        return row;
    }
}
