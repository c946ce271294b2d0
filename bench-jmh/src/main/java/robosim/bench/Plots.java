package robosim.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Draws the performance plots from what the benchmark scripts wrote in a directory (docs/perf):
 * results.csv (scripts/bench.sh), reset-interval.txt (bench-reset.sh), serialization.txt and
 * message-sizes.txt (bench-serialization.sh). Each figure is the median over the repetitions of the
 * newest sitting in results.csv. Also prints the medians as Markdown tables for PERFORMANCE.md.
 *
 * <p>usage: {@code java -cp ... robosim.bench.Plots docs/perf}
 */
public final class Plots {
    /** Stage 4.3 on these machines, from the performance issue: robots -> steps/s. */
    private static final Map<Integer, Double> STAGE = Map.of(10, 2075.0, 100, 122.0, 1000, 11.7);

    private Plots() {
    }

    public static void main(String[] args) throws IOException {
        Path dir = Path.of(args.length > 0 ? args[0] : "docs/perf");
        Map<String, List<Double>> runs = new LinkedHashMap<>();
        Map<String, List<Double>> ratios = new LinkedHashMap<>();
        Path csv = dir.resolve("results.csv");
        if (Files.exists(csv)) {
            readResults(csv, runs, ratios);
            scaling(dir, runs);
            designs(dir, runs, ratios);
            table(runs, ratios);
        }
        Path reset = dir.resolve("reset-interval.txt");
        if (Files.exists(reset)) {
            resetInterval(dir, reset);
        }
        Path ser = dir.resolve("serialization.txt");
        if (Files.exists(ser)) {
            serialization(dir, ser);
        }
    }

    /** Key: scenario|variant|robots|robots_in -> steps/s of each run (newest sitting only). */
    private static void readResults(Path csv, Map<String, List<Double>> runs, Map<String, List<Double>> ratios)
            throws IOException {
        for (Map<String, String> f : ResultsCsv.newest(ResultsCsv.read(csv), "steps_per_s")) {
            String key = f.get("scenario") + "|" + f.get("variant") + "|" + f.get("robots") + "|" + f.get("robots_in");
            runs.computeIfAbsent(key, k -> new ArrayList<>()).add(Double.parseDouble(f.get("steps_per_s")));
            String ratio = f.getOrDefault("ratio_to_floor", "");
            if (!ratio.isEmpty()) {
                ratios.computeIfAbsent(key, k -> new ArrayList<>()).add(Double.parseDouble(ratio));
            }
        }
    }

    private static double median(List<Double> values) {
        if (values == null || values.isEmpty()) {
            return Double.NaN;
        }
        List<Double> v = new ArrayList<>(values);
        Collections.sort(v);
        int n = v.size();
        return n % 2 == 1 ? v.get(n / 2) : (v.get(n / 2 - 1) + v.get(n / 2)) / 2;
    }

    private static void scaling(Path dir, Map<String, List<Double>> runs) throws IOException {
        XYChart chart = new XYChartBuilder().width(900).height(560)
                .title("Steps/s against robot count (Wander, 16 sonars every step, Geometry a process)")
                .xAxisTitle("robots").yAxisTitle("steps/s").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideSW);
        chart.getStyler().setMarkerSize(8);
        series(chart, "RoboSim, robots in one process", runs, "scaling|default|%d|one-process", 1, 10, 100, 1000);
        series(chart, "RoboSim, robots as processes", runs, "scaling|default|%d|processes", 1, 10);
        series(chart, "floor (Floor.java, same sitting)", runs, "floor|obj|%d|threads", 1, 10, 100, 1000);
        double[] sx = {10, 100, 1000};
        double[] sy = {STAGE.get(10), STAGE.get(100), STAGE.get(1000)};
        chart.addSeries("Stage 4.3 (from the issue)", sx, sy).setMarker(SeriesMarkers.DIAMOND);
        BitmapEncoder.saveBitmap(chart, dir.resolve("scaling").toString(), BitmapEncoder.BitmapFormat.PNG);
    }

    private static void series(XYChart chart, String name, Map<String, List<Double>> runs, String pattern,
            int... robots) {
        List<Double> x = new ArrayList<>();
        List<Double> y = new ArrayList<>();
        for (int n : robots) {
            double m = median(runs.get(String.format(Locale.ROOT, pattern, n)));
            if (!Double.isNaN(m)) {
                x.add((double) n);
                y.add(m);
            }
        }
        if (!x.isEmpty()) {
            chart.addSeries(name, x, y).setMarker(SeriesMarkers.CIRCLE);
        }
    }

    private static void designs(Path dir, Map<String, List<Double>> runs, Map<String, List<Double>> ratios)
            throws IOException {
        for (String scenario : List.of("paper", "designs")) {
            List<String> names = new ArrayList<>();
            List<Double> values = new ArrayList<>();
            for (Map.Entry<String, List<Double>> e : ratios.entrySet()) {
                String[] k = e.getKey().split("\\|");
                if (k[0].equals(scenario)) {
                    names.add(k[1]);
                    values.add(median(e.getValue()));
                }
            }
            if (names.isEmpty()) {
                continue;
            }
            boolean paper = scenario.equals("paper");
            CategoryChart chart = new CategoryChartBuilder().width(900).height(500)
                    .title((paper ? "Paper benchmark, 10 BackAndForth robot processes" : "bench-100, 100 Wander robots "
                            + "in one process") + ": each setting as a ratio to the floor")
                    .xAxisTitle("setting (the others at their defaults)").yAxisTitle("steps/s / floor steps/s").build();
            chart.getStyler().setLegendVisible(false);
            chart.getStyler().setXAxisLabelRotation(15);
            chart.addSeries(scenario, names, values);
            BitmapEncoder.saveBitmap(chart, dir.resolve(paper ? "designs-paper" : "designs-100").toString(),
                    BitmapEncoder.BitmapFormat.PNG);
        }
    }

    private static void table(Map<String, List<Double>> runs, Map<String, List<Double>> ratios) {
        System.out.println("| scenario | setting | robots | robots in | runs | median steps/s | median robot-steps/s "
                + "| median ratio to floor | Stage 4.3 |");
        System.out.println("|---|---|---|---|---|---|---|---|---|");
        for (Map.Entry<String, List<Double>> e : runs.entrySet()) {
            String[] k = e.getKey().split("\\|");
            int n = Integer.parseInt(k[2]);
            double m = median(e.getValue());
            double r = median(ratios.get(e.getKey()));
            Double stage = k[0].equals("scaling") ? STAGE.get(n) : null;
            System.out.printf(Locale.ROOT, "| %s | %s | %d | %s | %d | %.1f | %.0f | %s | %s |%n", k[0], k[1], n, k[3],
                    e.getValue().size(), m, m * n, Double.isNaN(r) ? "" : String.format(Locale.ROOT, "%.2f", r),
                    stage == null ? "" : stage.toString());
        }
    }

    private static void resetInterval(Path dir, Path file) throws IOException {
        // reset_every steps steps_per_s env_old_kb robots_old_kb geometry_old_kb; 0 = never
        TreeMap<Integer, double[]> rows = new TreeMap<>((a, b) -> Integer.compare(a == 0 ? Integer.MAX_VALUE : a,
                b == 0 ? Integer.MAX_VALUE : b));
        for (String line : Files.readAllLines(file)) {
            String[] f = line.trim().split("\\s+");
            if (f.length >= 6 && f[0].matches("\\d+")) {
                rows.put(Integer.parseInt(f[0]), new double[] {Double.parseDouble(f[2]), Double.parseDouble(f[3]),
                        Double.parseDouble(f[4]), Double.parseDouble(f[5])});
            }
        }
        if (rows.isEmpty()) {
            return;
        }
        List<String> names = new ArrayList<>();
        List<Double> speed = new ArrayList<>();
        List<Double> env = new ArrayList<>();
        List<Double> robots = new ArrayList<>();
        for (Map.Entry<Integer, double[]> e : rows.entrySet()) {
            names.add(e.getKey() == 0 ? "never" : "every " + e.getKey());
            speed.add(e.getValue()[0]);
            env.add(e.getValue()[1] / 1024);
            robots.add(e.getValue()[2] / 1024);
        }
        CategoryChart s = new CategoryChartBuilder().width(800).height(450)
                .title("Reset interval: speed (paper benchmark, 100,000 steps)").xAxisTitle("object-stream reset")
                .yAxisTitle("steps/s").build();
        s.getStyler().setLegendVisible(false);
        s.addSeries("steps/s", names, speed);
        BitmapEncoder.saveBitmap(s, dir.resolve("reset-speed").toString(), BitmapEncoder.BitmapFormat.PNG);
        CategoryChart h = new CategoryChartBuilder().width(800).height(450)
                .title("Reset interval: old generation after 100,000 steps").xAxisTitle("object-stream reset")
                .yAxisTitle("MB after a full GC").build();
        h.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        h.addSeries("Environment", names, env);
        h.addSeries("robots' JVM", names, robots);
        BitmapEncoder.saveBitmap(h, dir.resolve("reset-heap").toString(), BitmapEncoder.BitmapFormat.PNG);
    }

    private static void serialization(Path dir, Path file) throws IOException {
        Pattern p = Pattern.compile("writeAndRead\\s+(\\w+)\\s+(\\w+)\\s+avgt\\s+\\d+\\s+([0-9.]+)");
        Map<String, Map<String, Double>> byForm = new TreeMap<>();
        for (String line : Files.readAllLines(file)) {
            Matcher m = p.matcher(line);
            if (m.find()) {
                byForm.computeIfAbsent(m.group(1), k -> new TreeMap<>()).put(m.group(2), Double.parseDouble(m.group(3)));
            }
        }
        if (byForm.isEmpty()) {
            return;
        }
        CategoryChart c = new CategoryChartBuilder().width(800).height(450)
                .title("Serializable against Externalizable: write + read one message (JMH)")
                .xAxisTitle("message").yAxisTitle("ns per message").build();
        c.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        for (Map.Entry<String, Map<String, Double>> e : byForm.entrySet()) {
            c.addSeries(e.getKey(), new ArrayList<>(e.getValue().keySet()), new ArrayList<>(e.getValue().values()));
        }
        BitmapEncoder.saveBitmap(c, dir.resolve("serialization").toString(), BitmapEncoder.BitmapFormat.PNG);
    }
}
