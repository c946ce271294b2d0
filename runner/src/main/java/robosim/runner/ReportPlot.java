package robosim.runner;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.markers.SeriesMarkers;
import robosim.protocol.RecordingReader;
import robosim.protocol.Report;
import robosim.protocol.RobotView;
import robosim.protocol.StepNumbers;

/**
 * A reported value over a run as a PNG ({@code record-tool.sh plot FILE --report NAME --out FILE.png}): a line per
 * robot that reported {@code NAME}, its value at each step it reported one (steps completed on the x axis, as
 * {@code record-tool.sh reports} writes them). Drawn by XChart, headless.
 */
final class ReportPlot {
    private ReportPlot() {
    }

    /** Draws {@code name}'s values in {@code recording} into {@code png} (a new file); false if no robot reported it. */
    static boolean draw(RecordingReader recording, String name, Path png) throws IOException {
        Map<String, List<double[]>> byRobot = new LinkedHashMap<>();
        for (int k = 0; k < recording.steps(); k++) {
            RecordingReader.Step step = recording.step(k);
            List<String> names = recording.snapshotAt(k).robotNames();
            for (RobotView v : step.views()) {
                for (Report r : v.reports()) {
                    if (r.name().equals(name)) {
                        String robot = v.robot() < names.size() ? names.get(v.robot()) : "robot" + v.robot();
                        byRobot.computeIfAbsent(robot, x -> new ArrayList<>())
                                .add(new double[] {StepNumbers.shown(step.update().step()), r.value()});
                    }
                }
            }
        }
        if (byRobot.isEmpty()) {
            return false;
        }
        System.setProperty("java.awt.headless", "true");
        XYChart chart = new XYChartBuilder().width(800).height(500).title(name + " as reported, by robot")
                .xAxisTitle("step").yAxisTitle(name).build();
        byRobot.forEach((robot, points) -> {
            double[] x = points.stream().mapToDouble(p -> p[0]).toArray();
            double[] y = points.stream().mapToDouble(p -> p[1]).toArray();
            org.knowm.xchart.XYSeries series = chart.addSeries(robot, x, y);
            series.setMarker(SeriesMarkers.NONE);
            series.setXYSeriesRenderStyle(org.knowm.xchart.XYSeries.XYSeriesRenderStyle.Step); // (held until the next)
        });
        Path temporary = png.resolveSibling("." + png.getFileName() + ".tmp-" + ProcessHandle.current().pid());
        BitmapEncoder.saveBitmap(chart, temporary.toString(), BitmapEncoder.BitmapFormat.PNG);
        Files.move(temporary.resolveSibling(temporary.getFileName() + ".png"), png,
                java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        return true;
    }
}
