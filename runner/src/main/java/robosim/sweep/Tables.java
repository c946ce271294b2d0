package robosim.sweep;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.apache.commons.math3.distribution.TDistribution;
import robosim.environment.metrics.MetricInfo;
import robosim.environment.metrics.Metrics;
import org.apache.commons.math3.stat.descriptive.SummaryStatistics;

/**
 * The tables made from a sweep's rows: {@code runs.csv} (every row, by index, the columns of all of them) and
 * {@code summary.csv} (one row per combination of the parameters: how many runs, how many failed, and per metric
 * the mean, the sample standard deviation and the 95% confidence interval of the mean over the runs that succeeded:
 * a bootstrap percentile interval for the built-in metrics whose description asks for one (counts and shares: it
 * stays within their range), Student's t for every other metric). Each is written whole, then renamed into place.
 */
final class Tables {
    /** The metrics of the rows: every column that is neither the run's nor a parameter, in first-seen order. */
    final List<String> metrics;
    /** Each combination's statistics, by combination (parameter values in sweep order), in run order. */
    final Map<Map<String, String>, Map<String, SummaryStatistics>> byCombination = new LinkedHashMap<>();
    /** Each combination's values of each metric, in run order (the bootstrap's samples). */
    private final Map<Map<String, String>, Map<String, List<Double>>> samples = new LinkedHashMap<>();
    /** Runs and failed runs per combination. */
    final Map<Map<String, String>, int[]> counts = new LinkedHashMap<>();
    /** The bootstrap's resamples. */
    private static final int RESAMPLES = 10_000;
    private final Sweep sweep;
    private final List<Row> rows;
    private final List<String> columns;

    Tables(Sweep sweep, List<Row> rows) {
        this.sweep = sweep;
        this.rows = rows;
        Set<String> metricSet = new LinkedHashSet<>();
        Set<String> fixed = new LinkedHashSet<>(Row.FIRST);
        fixed.addAll(sweep.values().keySet());
        fixed.addAll(Row.RUN);
        fixed.addAll(Row.LAST);
        for (Row r : rows) {
            for (String c : r.values().keySet()) {
                if (!fixed.contains(c)) {
                    metricSet.add(c);
                }
            }
        }
        metrics = List.copyOf(metricSet);
        columns = new ArrayList<>(Row.FIRST);
        columns.addAll(sweep.values().keySet());
        columns.addAll(Row.RUN);
        columns.addAll(metrics);
        columns.addAll(Row.LAST);
        for (int c = 0; c < sweep.combinationCount(); c++) {
            byCombination.put(sweep.combination(c), new LinkedHashMap<>());
            samples.put(sweep.combination(c), new LinkedHashMap<>());
            counts.put(sweep.combination(c), new int[2]);
        }
        for (Row r : rows) {
            Map<String, String> combination = combinationOf(r);
            int[] n = counts.get(combination);
            if (n == null) {
                continue; // (not a combination of this sweep: ignored)
            }
            n[0]++;
            if (!r.ok()) {
                n[1]++;
                continue;
            }
            Map<String, SummaryStatistics> stats = byCombination.get(combination);
            for (String m : metrics) {
                double v = number(r, m);
                if (!Double.isNaN(v)) {
                    stats.computeIfAbsent(m, k -> new SummaryStatistics()).addValue(v);
                    samples.get(combination).computeIfAbsent(m, k -> new ArrayList<>()).add(v);
                }
            }
        }
    }

    /**
     * Metric {@code m} of row {@code r}: NaN when the row has none, or (a row damaged by hand) has something that is
     * not a number there, which is said once on stderr and left out.
     */
    static double number(Row r, String m) {
        String v = r.values().get(m);
        if (v == null || v.isEmpty()) {
            return Double.NaN;
        }
        try {
            double d = Double.parseDouble(v);
            if (Double.isFinite(d)) {
                return d;
            }
        } catch (NumberFormatException e) {
            // (said below)
        }
        if (SAID.add(r.index() + " " + m)) {
            System.err.println("sweep: run " + r.index() + ": " + m + " '" + robosim.protocol.Printable.of(v, 40)
                    + "' is not a number; left out of the summary and the plots");
        }
        return Double.NaN;
    }

    /** The row metrics already said not to be numbers. */
    private static final java.util.Set<String> SAID = java.util.concurrent.ConcurrentHashMap.newKeySet();

    private Map<String, String> combinationOf(Row r) {
        Map<String, String> c = new LinkedHashMap<>();
        for (String p : sweep.values().keySet()) {
            c.put(p, r.values().get(p));
        }
        return c;
    }

    /** Writes {@code runs.csv} and {@code summary.csv} into {@code dir}. */
    void write(Path dir) throws IOException {
        StringBuilder runs = new StringBuilder(Csv.line(columns));
        for (Row r : rows) {
            List<String> line = new ArrayList<>();
            for (String c : columns) {
                line.add(r.values().getOrDefault(c, ""));
            }
            runs.append(Csv.line(line));
        }
        replace(dir.resolve("runs.csv"), runs.toString());
        List<String> header = new ArrayList<>(sweep.values().keySet());
        header.addAll(List.of("runs", "failed"));
        for (String m : metrics) {
            header.addAll(List.of(m + "_mean", m + "_sd", m + "_ci95_low", m + "_ci95_high"));
        }
        StringBuilder summary = new StringBuilder(Csv.line(header));
        byCombination.forEach((combination, stats) -> {
            List<String> line = new ArrayList<>(combination.values());
            int[] n = counts.get(combination);
            line.add(Integer.toString(n[0]));
            line.add(Integer.toString(n[1]));
            for (String m : metrics) {
                SummaryStatistics s = stats.get(m);
                double[] ci = interval(combination, m);
                int places = s == null || s.getN() < 2 ? -1 : Csv.places(s.getStandardDeviation());
                line.add(s == null ? "" : Csv.number(s.getMean(), places));
                line.add(s == null || s.getN() < 2 ? "" : Csv.number(s.getStandardDeviation(), places));
                line.add(ci == null ? "" : Csv.number(ci[0], places));
                line.add(ci == null ? "" : Csv.number(ci[1], places));
            }
            summary.append(Csv.line(line));
        });
        replace(dir.resolve("summary.csv"), summary.toString());
        replace(dir.resolve("summary.txt"), text());
    }

    /**
     * The summary as a person reads it (the sweep prints it at its end; {@code summary.txt}): each combination, its
     * runs, then each metric's mean and 95% interval, written as summary.csv writes them.
     */
    String text() {
        StringBuilder out = new StringBuilder("mean and 95% interval over the runs that succeeded:\n");
        int width = metrics.stream().mapToInt(String::length).max().orElse(0);
        byCombination.forEach((combination, stats) -> {
            int[] n = counts.get(combination);
            String name = combination.isEmpty() ? "every run"
                    : String.join(" ", combination.entrySet().stream().map(e -> e.getKey() + "=" + e.getValue()).toList());
            out.append(name).append(" (").append(n[0]).append(n[0] == 1 ? " run" : " runs")
                    .append(n[1] > 0 ? ", " + n[1] + " failed" : "").append(")\n");
            for (String m : metrics) {
                SummaryStatistics s = stats.get(m);
                if (s == null) {
                    continue;
                }
                double[] ci = interval(combination, m);
                int places = s.getN() < 2 ? -1 : Csv.places(s.getStandardDeviation());
                out.append("  ").append(m).append(" ".repeat(width - m.length() + 2))
                        .append(Csv.number(s.getMean(), places));
                if (ci != null) {
                    out.append("  (").append(Csv.number(ci[0], places)).append(" to ")
                            .append(Csv.number(ci[1], places)).append(")");
                }
                out.append("\n");
            }
        });
        return out.toString();
    }

    /**
     * The 95% confidence interval of the mean of {@code metric} at {@code combination}: a bootstrap percentile one for
     * a built-in metric whose {@link MetricInfo#interval()} says so (counts and shares, which a t-interval can leave)
     * and a report the sweep file declares a count, else Student's t with n - 1 degrees of freedom; null for fewer
     * than 2 values.
     */
    double[] interval(Map<String, String> combination, String metric) {
        SummaryStatistics s = byCombination.get(combination).get(metric);
        if (s == null || s.getN() < 2) {
            return null;
        }
        MetricInfo builtIn = Metrics.info(metric);
        boolean count = sweep.metrics().stream().anyMatch(c -> c.countsIn(metric));
        if (count || builtIn != null && builtIn.interval() == MetricInfo.Interval.BOOTSTRAP) {
            return bootstrap(samples.get(combination).get(metric), (combination + " " + metric).hashCode());
        }
        double t = new TDistribution(null, s.getN() - 1).inverseCumulativeProbability(0.975);
        double half = t * s.getStandardDeviation() / Math.sqrt(s.getN());
        return new double[] {s.getMean() - half, s.getMean() + half};
    }

    /**
     * The 2.5th and 97.5th percentiles of the means of {@link #RESAMPLES} resamples (with replacement) of {@code
     * values}, drawn from a generator seeded with {@code seed}: the same values give the same interval.
     */
    static double[] bootstrap(List<Double> values, long seed) {
        java.util.SplittableRandom random = new java.util.SplittableRandom(seed);
        int n = values.size();
        double[] means = new double[RESAMPLES];
        for (int b = 0; b < RESAMPLES; b++) {
            double sum = 0;
            for (int i = 0; i < n; i++) {
                sum += values.get(random.nextInt(n));
            }
            means[b] = sum / n;
        }
        java.util.Arrays.sort(means);
        return new double[] {means[(int) Math.floor(0.025 * (RESAMPLES - 1))],
            means[(int) Math.ceil(0.975 * (RESAMPLES - 1))]};
    }

    private static void replace(Path file, String text) throws IOException {
        Path temporary = file.resolveSibling("." + file.getFileName() + ".tmp-" + ProcessHandle.current().pid());
        Files.writeString(temporary, text, StandardCharsets.UTF_8);
        Files.move(temporary, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
    }
}
