package robosim.runner;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import robosim.protocol.CommandLines;
import robosim.protocol.CommEvent;
import robosim.protocol.RecordingReader;
import robosim.protocol.RobotView;
import robosim.protocol.StepNumbers;
import robosim.sweep.Csv;

/**
 * {@code scripts/record-tool.sh}: what is in a recording ({@code --record}). {@code summary} prints the
 * world, the steps and how the run ended (or where the file stops); {@code poses} writes every step's
 * poses as CSV on stdout, the {@code --pose-log} columns; {@code messages} every message delivered as CSV
 * ({@code step,from,to,text}); {@code reports} every value the robots (and the loop functions, as {@code loop}) reported
 * as CSV ({@code step,robot,name,value});
 * {@code readings} every sensor reading as CSV, a value a row ({@code step,robot,sensor,unit,index,value}: the unit
 * its sensor's description in the registry gives, {@code Sensors});
 * {@code metrics} the run's metrics as a sweep's row has them (CSV: a header and a line), from the recording alone;
 * {@code plot} draws the robots' trajectories over the arena into a PNG ({@link TrajectoryPlot});
 * {@code export --mcap OUT.mcap} writes the run's ROS 2 messages into an MCAP file ({@link McapExport}: the ROS 2
 * bridge's topics, by Python's {@code robosim.ros2}).
 */
@Command(name = "record-tool.sh", mixinStandardHelpOptions = true,
        description = "Reads a recording made with --record (or kept by a sweep's --keep-recordings): summary, poses "
                + "(CSV), messages (CSV), reports (CSV: every value the robots and the loop functions reported, step by step), readings (CSV: "
                + "every sensor reading, a value a row, with its sensor's unit) or metrics (CSV: "
                + "the built-in metrics and every reported value, as a sweep's row has them; docs/EXPERIMENTS.md) on "
                + "stdout; plot draws each robot's trajectory over the arena and its obstacles into --out FILE.png; export "
                + "--mcap OUT.mcap writes the run as ROS 2 messages (the ROS 2 bridge's topics) into an MCAP file, with "
                + "$ROBOSIM_PYTHON's robosim.ros2 (pip install \"robosim[ros2]\").")
public final class RecordToolMain implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "summary|poses|messages|reports|readings|metrics|plot|export",
            description = "What to print (or draw, or export).")
    String what;

    @picocli.CommandLine.Option(names = "--out", paramLabel = "FILE.png", description = "With plot: the PNG to write "
            + "(a new file).")
    Path png;

    @picocli.CommandLine.Option(names = "--mcap", paramLabel = "OUT.mcap", description = "With export: the MCAP file "
            + "to write (a new file).")
    Path mcap;

    @picocli.CommandLine.Option(names = "--report", paramLabel = "NAME", description = "With plot: draw NAME's "
            + "reported values over the run, a line per robot, instead of the trajectories.")
    String report;

    @picocli.CommandLine.Option(names = "--size", paramLabel = "PX", description = "With plot: the arena's longer side, "
            + "px (default: 800).")
    int sizePx = 800;

    @picocli.CommandLine.Option(names = "--metric", paramLabel = "CLASS", description = "With metrics: these metrics "
            + "only, each a built-in's name, report:NAME (summed over the robots), report:NAME:OVER (OVER: sum, mean, "
            + "min, max or each) or a robosim.sweep.Metric class; repeat for more.")
    java.util.List<String> metrics = new java.util.ArrayList<>();

    @picocli.CommandLine.Mixin
    robosim.sweep.AreaCellOption areaCell;

    @Parameters(index = "1", paramLabel = "FILE", description = "The recording.")
    Path file;

    @Override
    public Integer call() throws Exception {
        if (!List.of("summary", "poses", "messages", "reports", "readings", "metrics", "plot", "export")
                .contains(what)) {
            System.err.println("record-tool: unknown request \"" + robosim.protocol.Printable.of(what, 40)
                    + "\" (summary, poses, messages, reports, readings, metrics, plot or export)");
            return 2;
        }
        if ((mcap != null) != what.equals("export")) {
            System.err.println("record-tool: " + (mcap == null ? "export needs --mcap OUT.mcap" : "--mcap goes with "
                    + "export"));
            return 2;
        }
        if (mcap != null) {
            return McapExport.export(file, mcap);
        }
        if (what.equals("metrics") && png == null && report == null) {
            return metrics();
        }
        if ((png != null || report != null) != what.equals("plot") || (report != null && png == null)) {
            System.err.println("record-tool: " + (what.equals("plot") ? "plot needs --out FILE.png"
                    : "--out and --report go with plot"));
            return 2;
        }
        if (png != null && java.nio.file.Files.exists(png)) {
            System.err.println("record-tool: " + png + ": exists already; give another --out");
            return 2;
        }
        if (sizePx < 100 || sizePx > 8000) {
            System.err.println("record-tool: --size must be 100 to 8000 px, got " + sizePx);
            return 2;
        }
        try (RecordingReader r = new RecordingReader(file)) {
            BufferedWriter out = new BufferedWriter(new OutputStreamWriter(System.out, StandardCharsets.UTF_8), 1 << 16);
            switch (what) {
                case "summary" -> summary(r, System.out);
                case "poses" -> poses(r, out);
                case "reports" -> reports(r, out);
                case "readings" -> readings(r, out);
                case "plot" -> {
                    if (report == null) {
                        TrajectoryPlot.draw(r, png, sizePx);
                    } else if (!ReportPlot.draw(r, report, png)) {
                        System.err.println("record-tool: " + file + ": no robot reported '"
                                + robosim.protocol.Printable.of(report, 64) + "'");
                        return 1;
                    }
                }
                default -> messages(r, out);
            }
            out.flush();
            return 0;
        } catch (IOException e) {
            System.err.println("record-tool: " + e.getMessage());
            return e.getMessage() != null && e.getMessage().startsWith(file.toString()) ? 2 : 1;
        }
    }

    private int metrics() {
        java.util.List<robosim.sweep.MetricChoice> chosen = new java.util.ArrayList<>();
        for (String m : metrics) {
            robosim.sweep.MetricChoice c = robosim.sweep.MetricChoice.parse(m);
            String bad = c.problem();
            if (bad != null) {
                System.err.println("record-tool: --metric " + m + ": " + bad);
                return 2;
            }
            chosen.add(c);
        }
        if (areaCell.problem() != null) {
            System.err.println("record-tool: " + areaCell.problem());
            return 2;
        }
        try {
            System.out.print(robosim.sweep.RunMetrics.csv(robosim.sweep.RunMetrics.of(file, chosen, areaCell.metres())));
            return 0;
        } catch (IOException e) {
            System.err.println("record-tool: " + e.getMessage());
            return e.getMessage() != null && e.getMessage().startsWith(file.toString()) ? 2 : 1;
        }
    }

    static void summary(RecordingReader r, PrintStream out) throws IOException {
        var s = r.snapshot();
        out.println("robots=" + s.robotNames().size() + " " + String.join(",", s.robotNames()));
        if (r.steps() > 0 && r.snapshotAt(r.steps() - 1) != s) {
            var last = r.snapshotAt(r.steps() - 1).robotNames();
            out.println("joined=" + (last.size() - s.robotNames().size()) + " "
                    + String.join(",", last.subList(s.robotNames().size(), last.size())));
        }
        out.println("time_step_ms=" + s.timeStepMs() + " obstacles=" + s.obstacles().size());
        out.println("steps=" + r.steps() + (r.steps() == 0 ? "" : " first=" + StepNumbers.shown(r.stepNumber(0))
                + " last=" + StepNumbers.shown(r.stepNumber(r.steps() - 1))));
        if (r.end() != null) {
            out.println("end=" + r.end().reason());
        } else {
            out.println("end=none: the file stops after step " + (r.steps() == 0 ? "-"
                    : robosim.protocol.StepNumbers.shown(r.stepNumber(r.steps() - 1)))
                    + (r.cutShort() == null ? "" : " (" + r.cutShort() + ")"));
        }
    }

    static void poses(RecordingReader r, BufferedWriter out) throws IOException {
        out.write(PoseLog.HEADER);
        for (int k = 0; k < r.steps(); k++) {
            PoseLog.write(r.step(k).update(), r.snapshotAt(k).robotNames(), out); // (robots may have joined)
        }
    }

    static void messages(RecordingReader r, BufferedWriter out) throws IOException {
        out.write(Csv.line(List.of("step", "from", "to", "text")));
        for (int k = 0; k < r.steps(); k++) {
            RecordingReader.Step s = r.step(k);
            for (RobotView v : s.views()) {
                for (CommEvent m : v.delivered()) {
                    out.write(Csv.line(List.of(Long.toString(StepNumbers.shown(s.update().step())), m.from(), m.to(),
                            m.payload())));
                }
            }
        }
    }

    /**
     * Every sensor reading, a value a row, with the step whose response carried it (steps completed, as {@code poses})
     * and the unit its sensor's description gives ({@code Sensors.kindOf} the reading's name: "" for a sensor of
     * one's own).
     */
    static void readings(RecordingReader r, BufferedWriter out) throws IOException {
        out.write(Csv.line(List.of("step", "robot", "sensor", "unit", "index", "value")));
        for (int k = 0; k < r.steps(); k++) {
            RecordingReader.Step s = r.step(k);
            List<String> names = r.snapshotAt(k).robotNames();
            String step = Long.toString(StepNumbers.shown(s.update().step()));
            for (RobotView v : s.views()) {
                String robot = v.robot() < names.size() ? names.get(v.robot()) : "robot" + v.robot();
                for (robosim.protocol.SensorReading reading : v.readings()) {
                    robosim.devices.SensorInfo kind = robosim.devices.Sensors.kindOf(reading.name(),
                            reading.values().length);
                    String unit = kind == null ? "" : kind.unit();
                    double[] values = reading.values();
                    for (int i = 0; i < values.length; i++) {
                        out.write(Csv.line(List.of(step, robot, reading.name(), unit, Integer.toString(i),
                                Double.toString(values[i]))));
                    }
                }
            }
        }
    }

    /**
     * Every value a robot reported, with the step whose request carried it (steps completed, as {@code poses}), then
     * the step's loop functions' metrics, as the robot {@code loop}'s.
     */
    static void reports(RecordingReader r, BufferedWriter out) throws IOException {
        out.write(Csv.line(List.of("step", "robot", "name", "value")));
        for (int k = 0; k < r.steps(); k++) {
            RecordingReader.Step s = r.step(k);
            List<String> names = r.snapshotAt(k).robotNames();
            for (RobotView v : s.views()) {
                for (robosim.protocol.Report report : v.reports()) {
                    out.write(Csv.line(List.of(Long.toString(StepNumbers.shown(s.update().step())),
                            v.robot() < names.size() ? names.get(v.robot()) : "robot" + v.robot(), report.name(),
                            Double.toString(report.value()))));
                }
            }
            for (robosim.protocol.Report report : s.update().reports()) { // (the loop functions', as a reporter "loop")
                out.write(Csv.line(List.of(Long.toString(StepNumbers.shown(s.update().step())),
                        robosim.environment.core.LoopSpec.SENDER, report.name(), Double.toString(report.value()))));
            }
        }
    }

    public static void main(String[] args) {
        CommandLines.exit("record-tool", new RecordToolMain(), args);
    }
}
