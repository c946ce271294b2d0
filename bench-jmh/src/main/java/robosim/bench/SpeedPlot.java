package robosim.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The speed table and plot from speed.csv (scripts/bench-speed.sh): for the newest sitting, the median
 * steps/s and ratio to its floor of each variant at 10, 100 and 1000 robots, printed as a Markdown table
 * beside ARGoS 3 and Stage 4.3 (measured in the same sitting when it has their rows, else the marks measured
 * once on this machine kind), and drawn (steps/s against robots, log-log) into speed.png.
 *
 * <p>usage: {@code java -cp ... robosim.bench.SpeedPlot DIR}
 */
public final class SpeedPlot {
    private static final int[] ROBOTS = {10, 100, 1000};
    /** ARGoS 3 and Stage 4.3 on this machine kind (the speed issue): robots 10, 100, 1000 -> steps/s. */
    private static final double[] ARGOS = {6540, 580, 39.9};
    private static final double[] STAGE = {3490, 194, 14.8};
    private static final List<String> VARIANTS = List.of("shared-connection", "THREADS-per-robot",
            "SEQUENTIAL-per-robot", "one-jvm", "FloorThreads", "FloorShared", "Engine");
    /** The peers' rows, when the sitting measured them (bench-speed.sh --peers). */
    private static final List<String> PEERS = List.of("ARGoS-3", "Stage-4.3");

    private SpeedPlot() {
    }

    public static void main(String[] args) throws IOException {
        Path dir = Path.of(args.length > 0 ? args[0] : "docs/perf");
        List<Map<String, String>> rows = ResultsCsv.newest(ResultsCsv.read(dir.resolve("speed.csv")), "steps_per_s");
        String newest = rows.isEmpty() ? "" : rows.get(0).get("sitting");
        Map<String, List<Double>> rates = new LinkedHashMap<>();
        Map<String, List<Double>> ratios = new LinkedHashMap<>();
        for (Map<String, String> f : rows) {
            String key = f.get("variant") + "|" + f.get("robots");
            rates.computeIfAbsent(key, k -> new ArrayList<>()).add(Double.parseDouble(f.get("steps_per_s")));
            String ratio = f.getOrDefault("ratio_to_floor", "");
            if (!ratio.isEmpty()) {
                ratios.computeIfAbsent(key, k -> new ArrayList<>()).add(Double.parseDouble(ratio));
            }
        }
        boolean peersMeasured = rates.keySet().stream().anyMatch(k -> k.startsWith(PEERS.get(0) + "|"));
        System.out.println("sitting " + newest + ": median steps/s (ratio to its floor); ARGoS 3 and Stage 4.3 "
                + (peersMeasured ? "measured in the same sitting (ratio: to Engine)"
                        : "are the marks measured once on this machine kind (the speed issue), not this sitting"));
        System.out.println();
        System.out.println("| robots | " + String.join(" | ", VARIANTS) + " | ARGoS 3 | Stage 4.3 |");
        System.out.println("|---|" + "---|".repeat(VARIANTS.size() + 2));
        for (int r = 0; r < ROBOTS.length; r++) {
            StringBuilder b = new StringBuilder("| " + ROBOTS[r] + " |");
            for (String v : VARIANTS) {
                String key = v + "|" + ROBOTS[r];
                double m = median(rates.get(key));
                b.append(String.format(Locale.ROOT, " %.1f", m));
                if (!v.startsWith("Floor") && !v.equals("Engine")) { // (a floor: its own ratio is 1)
                    b.append(String.format(Locale.ROOT, " (%.2f)", median(ratios.get(key))));
                }
                b.append(" |");
            }
            if (peersMeasured) {
                for (String v : PEERS) {
                    String key = v + "|" + ROBOTS[r];
                    b.append(String.format(Locale.ROOT, " %.1f (%.2f) |", median(rates.get(key)), median(ratios.get(key))));
                }
            } else {
                b.append(String.format(Locale.ROOT, " %.1f | %.1f |", ARGOS[r], STAGE[r]));
            }
            System.out.println(b);
        }
        XYChart chart = new XYChartBuilder().width(900).height(560)
                .title("Steps/s against robots (Wander, 16 sonars every step; " + newest + ")")
                .xAxisTitle("robots").yAxisTitle("steps/s").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideSW);
        chart.getStyler().setMarkerSize(8);
        for (String v : peersMeasured ? concat(VARIANTS, PEERS) : VARIANTS) {
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            for (int n : ROBOTS) {
                double m = median(rates.get(v + "|" + n));
                if (!Double.isNaN(m)) {
                    x.add((double) n);
                    y.add(m);
                }
            }
            if (!x.isEmpty()) {
                chart.addSeries(v, x, y).setMarker(SeriesMarkers.CIRCLE);
            }
        }
        if (!peersMeasured) {
            double[] xs = {10, 100, 1000};
            chart.addSeries("ARGoS 3 (the issue's mark)", xs, ARGOS).setMarker(SeriesMarkers.DIAMOND);
            chart.addSeries("Stage 4.3 (the issue's mark)", xs, STAGE).setMarker(SeriesMarkers.DIAMOND);
        }
        BitmapEncoder.saveBitmap(chart, dir.resolve("speed").toString(), BitmapEncoder.BitmapFormat.PNG);
    }

    private static List<String> concat(List<String> a, List<String> b) {
        List<String> all = new ArrayList<>(a);
        all.addAll(b);
        return all;
    }

    private static double median(List<Double> values) {
        if (values == null || values.isEmpty()) {
            return Double.NaN;
        }
        List<Double> v = new ArrayList<>(values);
        v.sort(null);
        int m = v.size();
        return m % 2 == 1 ? v.get(m / 2) : (v.get(m / 2 - 1) + v.get(m / 2)) / 2;
    }
}
