package robosim.sweep;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import robosim.protocol.Arena;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.Report;
import robosim.protocol.RobotView;
import robosim.protocol.WorldSnapshot;

/**
 * A run's metrics, read from its recording alone (one pass over its steps), so a kept recording gives its row
 * again ({@code scripts/record-tool.sh metrics FILE}):
 * <ul>
 * <li>{@code distance_m}: the robots' paths, summed, m (each robot's straight moves from step to step);
 * <li>{@code contacts}: times a robot touched something (a step with a contact after one without);
 * <li>{@code messages_delivered}: messages delivered to robots;
 * <li>{@code tags}: tags made (a robot's tag that hit a robot or a taggable obstacle);
 * <li>{@code area_covered}: the share of the arena's square cells (side {@code areaCellM}) a robot's centre has
 * been in at the end of some step, 0 to 1;
 * <li>{@code robots_left}: robots still in the world at the end;
 * <li>each name the control code reported ({@code Robot.report}): each robot's newest value, summed over the
 * robots that reported it (a name that is also a built-in's or a row's own column, {@code seed} say, is
 * {@code report.NAME}), or as a sweep file's {@code over} says ({@link MetricChoice#column});
 * <li>each {@link Metric} class asked for, by its {@link Metric#name()}.
 * </ul>
 */
public final class RunMetrics {
    /** The built-in metrics, in their column order. */
    public static final List<String> BUILT_IN = List.of("distance_m", "contacts", "messages_delivered", "tags",
            "area_covered", "robots_left");
    /** The side of {@code area_covered}'s cells unless a sweep says otherwise, m. */
    public static final double DEFAULT_AREA_CELL_M = 0.5;
    /** The most cells {@code area_covered} counts (one bit each). */
    static final long MAX_AREA_CELLS = 1L << 26;

    private RunMetrics() {
    }

    /**
     * A run's metrics and what its robots reported.
     *
     * @param values the metrics, by column, in the chosen order
     * @param unreported the chosen reports no robot made in this run (their columns are left out)
     * @param reported every name a robot reported, in alphabetical order
     */
    public record Measured(Map<String, Double> values, List<String> unreported, List<String> reported) {
    }

    /**
     * The metrics {@code chosen} asks for, in its order (none chosen: every built-in one, then every reported name
     * in alphabetical order), of the recording {@code file}; a report no robot made is left out.
     */
    public static Map<String, Double> of(Path file, List<MetricChoice> chosen, double areaCellM) throws IOException {
        return measure(file, chosen, areaCellM).values();
    }

    /** As {@link #of}, saying which chosen reports no robot made, and what was reported. */
    public static Measured measure(Path file, List<MetricChoice> chosen, double areaCellM) throws IOException {
        try (RecordingReader recording = new RecordingReader(file)) {
            Map<String, Map<String, Double>> reports = new TreeMap<>();
            Map<String, Double> all = builtInAndReports(recording, areaCellM, reports);
            List<String> reported = List.copyOf(reports.keySet());
            Map<String, Double> out = new LinkedHashMap<>();
            List<String> unreported = new java.util.ArrayList<>();
            if (chosen.isEmpty()) {
                return new Measured(all, unreported, reported);
            }
            for (MetricChoice c : chosen) {
                switch (c.kind()) {
                    case BUILT_IN -> out.put(c.name(), all.get(c.name()));
                    case REPORT -> {
                        Map<String, Double> byRobot = reports.get(c.name());
                        if (byRobot == null) {
                            unreported.add(c.name());
                        } else {
                            over(c, byRobot, out);
                        }
                    }
                    case CLASS -> {
                        Metric m;
                        try {
                            m = c.instance();
                        } catch (ReflectiveOperationException | LinkageError e) {
                            throw new IOException("metric class " + c.name() + ": " + e);
                        }
                        double v = m.value(recording);
                        if (Report.problem(m.name(), v) != null) {
                            throw new IOException("metric class " + c.name() + ": " + Report.problem(m.name(), v));
                        }
                        out.put(m.name(), v);
                    }
                }
            }
            return new Measured(out, unreported, reported);
        }
    }

    /** Report {@code c}'s column(s) from {@code byRobot} (each robot's newest value, in the robots' order) into {@code out}. */
    private static void over(MetricChoice c, Map<String, Double> byRobot, Map<String, Double> out) {
        java.util.DoubleSummaryStatistics s = byRobot.values().stream().mapToDouble(Double::doubleValue)
                .summaryStatistics();
        if (c.over() == MetricChoice.Over.EACH) {
            byRobot.forEach((robot, value) -> out.put(c.column(robot), value));
            return;
        }
        double value = c.over() == null ? s.getSum() : switch (c.over()) {
            case SUM -> s.getSum();
            case MEAN -> s.getAverage();
            case MIN -> s.getMin();
            case MAX -> s.getMax();
            case EACH -> throw new IllegalStateException("each: a column per robot");
        };
        out.put(c.column(null), value);
    }

    /** {@code metrics} as CSV: a header line and a value line, the numbers as a sweep's tables write them. */
    public static String csv(Map<String, Double> metrics) {
        List<String> values = new java.util.ArrayList<>();
        metrics.values().forEach(v -> values.add(Csv.number(v)));
        return Csv.line(new java.util.ArrayList<>(metrics.keySet())) + Csv.line(values);
    }

    /** Why cells of {@code areaCellM} are too many for {@code arena}'s {@code area_covered}, or null. */
    public static String cellProblem(Arena arena, double areaCellM) {
        double cells = Math.ceil((arena.maxXMm() - arena.minXMm()) / (areaCellM * 1000))
                * Math.ceil((arena.maxYMm() - arena.minYMm()) / (areaCellM * 1000));
        return cells <= MAX_AREA_CELLS ? null : "area cells of " + areaCellM + " m make " + (long) cells + " cells of this "
                + "arena, at most " + MAX_AREA_CELLS;
    }

    /** The column of a reported name: the name, or {@code report.NAME} where a built-in or a row's own column has it. */
    static String reportColumn(String name) {
        return reserved(name) ? "report." + name : name;
    }

    /** A column name of a built-in metric or of every row ({@link Row}): no reported or own metric may take it. */
    static boolean reserved(String name) {
        return BUILT_IN.contains(name) || Row.FIRST.contains(name) || Row.RUN.contains(name) || Row.LAST.contains(name);
    }

    /**
     * The built-in metrics and every reported name summed over the robots, of {@code recording}; into {@code reports}
     * each reported name's newest value per robot (by robot name, in the robots' order).
     */
    private static Map<String, Double> builtInAndReports(RecordingReader recording, double areaCellM,
            Map<String, Map<String, Double>> reports) throws IOException {
        WorldSnapshot world = recording.snapshot();
        PoseUpdate start = world.poses(); // (where the robots stood before step 0: its moves count too)
        double[] startX = new double[start.count()];
        double[] startY = new double[start.count()];
        for (int r = 0; r < start.count(); r++) {
            startX[r] = start.xMm(r);
            startY[r] = start.yMm(r);
        }
        RunTally tally;
        try {
            tally = new RunTally(world.arena(), areaCellM, startX, startY);
        } catch (IllegalArgumentException e) {
            throw new IOException(e.getMessage());
        }
        Map<Integer, Map<String, Double>> byIndex = new TreeMap<>();
        PoseUpdate last = world.poses();
        for (int i = 0; i < recording.steps(); i++) {
            RecordingReader.Step step = recording.step(i);
            PoseUpdate u = step.update();
            for (int r = 0; r < u.count(); r++) {
                tally.pose(r, u.xMm(r), u.yMm(r));
            }
            for (RobotView v : step.views()) {
                int r = v.robot();
                tally.contact(r, !v.contact().isEmpty());
                tally.delivered(v.delivered().size());
                for (Report report : v.reports()) {
                    byIndex.computeIfAbsent(r, k -> new HashMap<>()).put(report.name(), report.value());
                }
            }
            last = u;
        }
        List<String> names = recording.steps() == 0 ? world.robotNames()
                : recording.snapshotAt(recording.steps() - 1).robotNames();
        int robots = names.size();
        Map<String, Double> out = new LinkedHashMap<>();
        out.put("distance_m", tally.distanceM());
        out.put("contacts", (double) tally.contacts());
        out.put("messages_delivered", (double) tally.delivered());
        out.put("tags", (double) last.tags().size());
        out.put("area_covered", tally.areaCovered());
        out.put("robots_left", (double) Math.max(0, robots - last.departed().size()));
        Map<String, Double> summed = new TreeMap<>();
        byIndex.forEach((r, each) -> each.forEach((name, value) -> {
            summed.merge(reportColumn(name), value, Double::sum);
            reports.computeIfAbsent(name, k -> new LinkedHashMap<>()).put(r < names.size() ? names.get(r) : "robot" + r,
                    value);
        }));
        out.putAll(summed);
        return out;
    }
}
