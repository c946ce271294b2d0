package robosim.sweep;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import robosim.environment.metrics.AreaCoveredMetric;
import robosim.environment.metrics.MetricTally;
import robosim.environment.metrics.Metrics;
import robosim.environment.metrics.RunStart;
import robosim.environment.metrics.StepView;
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
 * <li>every built-in metric ({@link Metrics}), counted by the same code that counts it live, each step of the
 * recording read back as the step's {@link StepView};
 * <li>each name the control code reported ({@code Robot.report}) or the world's loop functions did
 * ({@code Experiment.report}, as one more reporter named {@code loop}): each reporter's newest value, summed over
 * the reporters (a name that is also a built-in's or a row's own column, {@code seed} say, is
 * {@code report.NAME}), or as a sweep file's {@code over} says ({@link MetricChoice#column});
 * <li>each {@link Metric} class asked for, by its {@link Metric#name()}.
 * </ul>
 */
public final class RunMetrics {
    /** The side of {@code area_covered}'s cells unless a sweep says otherwise, m. */
    public static final double DEFAULT_AREA_CELL_M = AreaCoveredMetric.DEFAULT_CELL_M;

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
        return AreaCoveredMetric.cellProblem(arena, areaCellM);
    }

    /** The column of a reported name: the name, or {@code report.NAME} where a built-in or a row's own column has it. */
    static String reportColumn(String name) {
        return reserved(name) ? "report." + name : name;
    }

    /** A column name of a built-in metric or of every row ({@link Row}): no reported or own metric may take it. */
    static boolean reserved(String name) {
        return Metrics.info(name) != null || Row.FIRST.contains(name) || Row.RUN.contains(name) || Row.LAST.contains(name);
    }

    /**
     * The built-in metrics and every reported name summed over the robots, of {@code recording}; into {@code reports}
     * each reported name's newest value per robot (by robot name, in the robots' order).
     */
    private static Map<String, Double> builtInAndReports(RecordingReader recording, double areaCellM,
            Map<String, Map<String, Double>> reports) throws IOException {
        WorldSnapshot world = recording.snapshot();
        String tooMany = AreaCoveredMetric.cellProblem(world.arena(), areaCellM);
        if (tooMany != null) {
            throw new IOException(tooMany);
        }
        RecordedStep step = new RecordedStep();
        step.read(world.poses(), List.of()); // (where the robots stood before step 0: its moves count too)
        MetricTally tally = new MetricTally(new RunStart(world.arena(), areaCellM, step));
        Map<Integer, Map<String, Double>> byIndex = new TreeMap<>();
        Map<String, Double> experiment = new LinkedHashMap<>(); // (the loop functions': each name's newest value)
        for (int i = 0; i < recording.steps(); i++) {
            RecordingReader.Step recorded = recording.step(i);
            step.read(recorded.update(), recorded.views());
            tally.step(step);
            for (Report report : recorded.update().reports()) {
                experiment.put(report.name(), report.value());
            }
            for (RobotView v : recorded.views()) {
                for (Report report : v.reports()) {
                    byIndex.computeIfAbsent(v.robot(), k -> new HashMap<>()).put(report.name(), report.value());
                }
            }
        }
        List<String> names = recording.steps() == 0 ? world.robotNames()
                : recording.snapshotAt(recording.steps() - 1).robotNames();
        Map<String, Double> out = new LinkedHashMap<>();
        for (int m = 0; m < tally.size(); m++) {
            out.put(tally.info(m).name(), tally.value(m));
        }
        Map<String, Double> summed = new TreeMap<>();
        byIndex.forEach((r, each) -> each.forEach((name, value) -> {
            summed.merge(reportColumn(name), value, Double::sum);
            reports.computeIfAbsent(name, k -> new LinkedHashMap<>()).put(r < names.size() ? names.get(r) : "robot" + r,
                    value);
        }));
        experiment.forEach((name, value) -> {
            summed.merge(reportColumn(name), value, Double::sum);
            reports.computeIfAbsent(name, k -> new LinkedHashMap<>()).put(LOOP, value);
        });
        out.putAll(summed);
        return out;
    }

    /** Whose a loop functions' metric is, among the robots' reports of the same name. */
    private static final String LOOP = "loop";

    /** A recorded step as the metrics see it: the update's poses, tags and departures, and each view's robot. */
    private static final class RecordedStep implements StepView {
        private PoseUpdate update;
        private boolean[] tookPart = new boolean[0];
        private boolean[] touching = new boolean[0];
        private int[] delivered = new int[0];

        void read(PoseUpdate u, List<RobotView> views) {
            update = u;
            if (tookPart.length < u.count()) {
                tookPart = new boolean[u.count()];
                touching = new boolean[u.count()];
                delivered = new int[u.count()];
            }
            java.util.Arrays.fill(tookPart, false);
            for (RobotView v : views) {
                int r = v.robot();
                if (r >= 0 && r < u.count()) {
                    tookPart[r] = true;
                    touching[r] = !v.contact().isEmpty();
                    delivered[r] = v.delivered().size();
                }
            }
        }

        @Override
        public int robots() {
            return update.count();
        }

        @Override
        public double xMm(int robot) {
            return update.xMm(robot);
        }

        @Override
        public double yMm(int robot) {
            return update.yMm(robot);
        }

        @Override
        public boolean tookPart(int robot) {
            return tookPart[robot];
        }

        @Override
        public boolean touching(int robot) {
            return touching[robot];
        }

        @Override
        public int delivered(int robot) {
            return delivered[robot];
        }

        @Override
        public int tags() {
            return update.tags().size();
        }

        @Override
        public int departed() {
            return update.departed().size();
        }
    }
}
