package robosim.sweep;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.apache.commons.math3.stat.descriptive.SummaryStatistics;
import robosim.environment.metrics.MetricInfo;
import robosim.environment.metrics.Metrics;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.Chart;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * A PNG per metric against each parameter the sweep varies ({@code plots/METRIC-vs-PARAM.png}): the mean of the
 * runs that succeeded at each value, with its 95% confidence interval ({@link Tables#interval}) as error bars (on bars,
 * for values that are not numbers, the interval's larger side both ways), one line per combination of
 * the other varied parameters. Numbers on the x axis when every value is one, else categories. A sweep that varies
 * no parameter gets a plot per metric against the seed, one point per run. Drawn by XChart, headless.
 */
final class Plots {
    private static final int WIDTH = 800;
    private static final int HEIGHT = 500;

    private Plots() {
    }

    /** Draws every plot of {@code tables} into {@code dir}/plots; returns the files written. */
    static List<Path> write(Sweep sweep, Tables tables, List<Row> rows, Path dir) throws IOException {
        System.setProperty("java.awt.headless", "true");
        Path plots = dir.resolve("plots");
        Files.createDirectories(plots);
        List<Path> written = new ArrayList<>();
        List<String> varied = new ArrayList<>();
        sweep.values().forEach((name, values) -> {
            if (values.size() > 1) {
                varied.add(name);
            }
        });
        for (String metric : tables.metrics) {
            if (tables.byCombination.values().stream().noneMatch(stats -> stats.containsKey(metric))) {
                continue; // (no run that succeeded has a value: no plot)
            }
            String axis = axis(sweep, metric);
            if (varied.isEmpty()) {
                written.add(save(bySeed(metric, axis, rows), plots.resolve(metric + "-vs-seed")));
            }
            for (String parameter : varied) {
                written.add(save(against(sweep, tables, metric, axis, parameter, varied), plots.resolve(metric + "-vs-"
                        + parameter)));
            }
        }
        return written;
    }

    /** The y axis of metric column {@code metric}: its name, with its unit or what it is over the robots. */
    static String axis(Sweep sweep, String metric) {
        MetricInfo builtIn = Metrics.info(metric);
        String unit = builtIn == null ? null : builtIn.unit();
        if (unit == null) {
            MetricChoice owner = sweep.owner(metric);
            if (owner != null) {
                unit = owner.over() == null || owner.over() == MetricChoice.Over.SUM ? "reported, summed over the reporters"
                        : owner.over() == MetricChoice.Over.EACH ? "reported by robot "
                        + metric.substring(owner.name().length() + 1)
                        : "reported, " + owner.over().written() + " over the robots";
            }
            if (unit == null && sweep.metrics().isEmpty() && builtIn == null) {
                unit = "reported, summed over the reporters";
            }
        }
        return unit == null ? metric : metric + " (" + unit + ")";
    }

    private static Path save(Chart<?, ?> chart, Path withoutExtension) throws IOException {
        BitmapEncoder.saveBitmap(chart, withoutExtension.toString(), BitmapEncoder.BitmapFormat.PNG);
        return withoutExtension.resolveSibling(withoutExtension.getFileName() + ".png");
    }

    /** One point per successful run: the metric against its seed. */
    private static XYChart bySeed(String metric, String axis, List<Row> rows) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(metric + " by seed").xAxisTitle("seed")
                .yAxisTitle(axis).build();
        List<Double> x = new ArrayList<>();
        List<Double> y = new ArrayList<>();
        for (Row r : rows) {
            double v = Tables.number(r, metric);
            if (r.ok() && !Double.isNaN(v)) {
                x.add(Double.parseDouble(r.values().get("seed")));
                y.add(v);
            }
        }
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        chart.getStyler().setLegendVisible(false);
        if (!x.isEmpty()) {
            chart.addSeries("runs", x, y);
        }
        return chart;
    }

    /** The metric's mean and interval at each value of {@code parameter}, a line per setting of the other varied ones. */
    private static Chart<?, ?> against(Sweep sweep, Tables tables, String metric, String axis, String parameter,
            List<String> varied) {
        List<String> values = sweep.values().get(parameter);
        boolean numeric = values.stream().allMatch(Plots::isNumber);
        // label -> {mean[], the interval's midpoint[], its half-width[]} by value index (a bootstrap interval is not
        // centred on the mean: its bars are a series of their own, drawn about its midpoint)
        Map<String, double[][]> lines = new LinkedHashMap<>();
        tables.byCombination.forEach((combination, stats) -> {
            StringBuilder label = new StringBuilder();
            for (String other : varied) {
                if (!other.equals(parameter)) {
                    label.append(label.length() == 0 ? "" : ", ").append(other).append('=').append(combination.get(other));
                }
            }
            double[][] line = lines.computeIfAbsent(label.length() == 0 ? metric : label.toString(), k -> {
                double[][] empty = new double[3][values.size()];
                java.util.Arrays.fill(empty[0], Double.NaN);
                return empty;
            });
            int at = values.indexOf(combination.get(parameter));
            SummaryStatistics s = stats.get(metric);
            if (s != null && s.getN() > 0) {
                line[0][at] = s.getMean();
                double[] ci = tables.interval(combination, metric);
                line[1][at] = ci == null ? s.getMean() : (ci[0] + ci[1]) / 2;
                line[2][at] = ci == null ? 0 : (ci[1] - ci[0]) / 2;
            }
        });
        String title = metric + " vs " + parameter + " (mean, 95% CI)";
        if (numeric) {
            XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title).xAxisTitle(parameter)
                    .yAxisTitle(axis).build();
            chart.getStyler().setLegendVisible(lines.size() > 1);
            double[] x = values.stream().mapToDouble(Double::parseDouble).toArray();
            lines.forEach((label, line) -> {
                List<Double> xs = new ArrayList<>();
                List<Double> ys = new ArrayList<>();
                List<Double> middles = new ArrayList<>();
                List<Double> errors = new ArrayList<>();
                for (int i = 0; i < x.length; i++) {
                    if (!Double.isNaN(line[0][i])) {
                        xs.add(x[i]);
                        ys.add(line[0][i]);
                        middles.add(line[1][i]);
                        errors.add(line[2][i]);
                    }
                }
                if (!xs.isEmpty()) {
                    chart.addSeries(label, xs, ys).setMarker(SeriesMarkers.CIRCLE);
                    XYSeries bars = chart.addSeries(label + ", 95% CI", xs, middles, errors);
                    bars.setMarker(SeriesMarkers.NONE);
                    bars.setLineStyle(org.knowm.xchart.style.lines.SeriesLines.NONE);
                    bars.setShowInLegend(false);
                }
            });
            return chart;
        }
        CategoryChart chart = new CategoryChartBuilder().width(WIDTH).height(HEIGHT).title(title).xAxisTitle(parameter)
                .yAxisTitle(axis).build();
        chart.getStyler().setLegendVisible(lines.size() > 1);
        lines.forEach((label, line) -> {
            List<String> xs = new ArrayList<>();
            List<Double> ys = new ArrayList<>();
            List<Double> errors = new ArrayList<>();
            for (int i = 0; i < values.size(); i++) {
                if (!Double.isNaN(line[0][i])) { // (a value without a successful run: no bar)
                    xs.add(values.get(i));
                    ys.add(line[0][i]);
                    // (bars' error bars are centred on the mean: the interval's larger side, both ways)
                    errors.add(Math.abs(line[1][i] - line[0][i]) + line[2][i]);
                }
            }
            if (!xs.isEmpty()) {
                chart.addSeries(label, xs, ys, errors);
            }
        });
        return chart;
    }

    private static boolean isNumber(String s) {
        try {
            return Double.isFinite(Double.parseDouble(s));
        } catch (NumberFormatException e) {
            return false;
        }
    }
}
