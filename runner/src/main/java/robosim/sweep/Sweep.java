package robosim.sweep;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A checked sweep: the world, the steps, the seeds, each varied parameter's values, how each run is laid out and
 * what it measures. Its runs are numbered from 0: every combination of the values (the first parameter's values
 * change slowest), then every seed, then every repetition; the same file numbers them the same anywhere.
 *
 * @param file the sweep file (absolute)
 * @param world the environment file (absolute)
 * @param values each varied parameter's values, in the file's order
 * @param runTimeoutS how long one run may take, s (0: no limit)
 * @param jvmOptions the JVM options of each run's process
 * @param metrics the metrics asked for (none: every built-in one and every report)
 * @param areaCellM the side of the grid's cells {@code area_covered} counts, m
 */
public record Sweep(Path file, Path world, long steps, long seedFrom, long seedTo, int repeat,
        Map<String, List<String>> values, Layout layout, long runTimeoutS, List<String> jvmOptions,
        List<MetricChoice> metrics, double areaCellM) {
    /**
     * The runs' JVM options unless a sweep file says otherwise ({@code jvm="..."}): for many short runs at once,
     * compile with C1 alone and collect with one thread, which costs a short run about a third less CPU (its JVM does
     * not spend a second core on C2 and parallel GC threads) and a long one about as much
     * ({@code docs/PERFORMANCE.md}, "Sweeps"). {@code jvm=""}: the JVM's defaults, for long runs of large worlds.
     */
    public static final List<String> SHORT_RUNS = List.of("-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC");

    /** How each run's parts are laid out: the headless runner's options for it. */
    public enum Layout {
        /** Everything in one JVM ({@code headless.sh --one-jvm}): the default, about one core a run. */
        ONE_JVM("--one-jvm"),
        /** Every part its own process, as the report's design runs. */
        PROCESSES(),
        /** The Environment and Geometry processes, every robot in one more ({@code --robots-in-one-process}). */
        ONE_PROCESS("--robots-in-one-process");

        private final List<String> options;

        Layout(String... options) {
            this.options = List.of(options);
        }

        /** The headless runner's options for this layout. */
        List<String> options() {
            return options;
        }

        /** As written in a sweep file: one-jvm, processes, one-process. */
        String written() {
            return name().toLowerCase(Locale.ROOT).replace('_', '-');
        }

        static Layout of(String written) {
            for (Layout l : values()) {
                if (l.written().equals(written)) {
                    return l;
                }
            }
            throw new IllegalArgumentException(written);
        }

        static String names() {
            return String.join(", ", Arrays.stream(values()).map(Layout::written).toList());
        }
    }

    /** One run of the sweep: its number, seed, repetition (from 1) and parameter values. */
    public record Run(int index, long seed, int repetition, Map<String, String> parameters) {
    }

    public Sweep {
        Map<String, List<String>> copy = new LinkedHashMap<>();
        values.forEach((name, list) -> copy.put(name, List.copyOf(list)));
        values = Collections.unmodifiableMap(copy);
        metrics = List.copyOf(metrics);
        jvmOptions = List.copyOf(jvmOptions);
    }

    /** Seeds in the range. */
    long seeds() {
        return seedTo - seedFrom + 1;
    }

    /** Combinations of the values (1 when nothing is varied). */
    long combinationCount() {
        long n = 1;
        for (List<String> v : values.values()) {
            n = Math.multiplyExact(n, v.size());
        }
        return n;
    }

    /** Every run, saturated at {@link Long#MAX_VALUE}. */
    public long runs() {
        try {
            return Math.multiplyExact(Math.multiplyExact(combinationCount(), seeds()), repeat);
        } catch (ArithmeticException e) {
            return Long.MAX_VALUE;
        }
    }

    /** Every combination of the values, in run order. */
    List<Map<String, String>> combinations() {
        List<Map<String, String>> all = new ArrayList<>();
        int n = (int) combinationCount();
        for (int c = 0; c < n; c++) {
            all.add(combination(c));
        }
        return all;
    }

    /** Combination {@code c}: the first parameter's values change slowest. */
    Map<String, String> combination(int c) {
        Map<String, String> out = new LinkedHashMap<>();
        int rest = c;
        List<String> names = new ArrayList<>(values.keySet());
        int[] pick = new int[names.size()];
        for (int p = names.size() - 1; p >= 0; p--) {
            List<String> v = values.get(names.get(p));
            pick[p] = rest % v.size();
            rest /= v.size();
        }
        for (int p = 0; p < names.size(); p++) {
            out.put(names.get(p), values.get(names.get(p)).get(pick[p]));
        }
        return Collections.unmodifiableMap(out);
    }

    /** The index of the run of {@code parameters}, {@code seed} and {@code repetition}, or -1 if it is no run of this sweep. */
    long indexOf(Map<String, String> parameters, long seed, int repetition) {
        if (!parameters.keySet().equals(values.keySet()) || seed < seedFrom || seed > seedTo || repetition < 1
                || repetition > repeat) {
            return -1;
        }
        long c = 0;
        for (Map.Entry<String, List<String>> p : values.entrySet()) {
            int at = p.getValue().indexOf(parameters.get(p.getKey()));
            if (at < 0) {
                return -1;
            }
            c = c * p.getValue().size() + at;
        }
        return (c * seeds() + (seed - seedFrom)) * repeat + repetition - 1;
    }

    /**
     * What keeps {@code later} from growing this sweep (more seeds, values or repetitions, nothing else changed), or
     * null if it does grow it.
     */
    String growthProblem(Sweep later) {
        if (!world.equals(later.world) || steps != later.steps || layout != later.layout
                || runTimeoutS != later.runTimeoutS || !jvmOptions.equals(later.jvmOptions)
                || !metrics.equals(later.metrics) || areaCellM != later.areaCellM) {
            return "its world, steps, layout, run timeout, JVM options or metrics differ";
        }
        if (!List.copyOf(values.keySet()).equals(List.copyOf(later.values.keySet()))) {
            return "its parameters differ (" + values.keySet() + " there, " + later.values.keySet() + " now)";
        }
        if (later.seedFrom > seedFrom || later.seedTo < seedTo || later.repeat < repeat) {
            return "its seeds " + seedFrom + " to " + seedTo + " (x " + repeat + ") are not all in " + later.seedFrom + " to "
                    + later.seedTo + " (x " + later.repeat + ")";
        }
        for (Map.Entry<String, List<String>> p : values.entrySet()) {
            if (!later.values.get(p.getKey()).containsAll(p.getValue())) {
                return "its values of " + p.getKey() + " " + p.getValue() + " are not all in " + later.values.get(p.getKey());
            }
        }
        return null;
    }

    /** Run {@code index} (0 to {@link #runs()} - 1). */
    public Run run(int index) {
        if (index < 0 || index >= runs()) {
            throw new IllegalArgumentException("run " + index + " of a sweep of " + runs());
        }
        long perCombination = seeds() * repeat;
        int c = (int) (index / perCombination);
        long within = index % perCombination;
        return new Run(index, seedFrom + within / repeat, (int) (within % repeat) + 1, combination(c));
    }

    /**
     * The report choice of this sweep whose column {@code column} is, or null: a report's own column (a row writes
     * {@code report.NAME} where a parameter has the name), {@code NAME.robot_OVER}, else {@code NAME.ROBOT} of an
     * {@code over="each"} one.
     */
    MetricChoice owner(String column) {
        MetricChoice each = null;
        for (MetricChoice c : metrics) {
            if (c.kind() != MetricChoice.Kind.REPORT) {
                continue;
            }
            if (c.over() == MetricChoice.Over.EACH) {
                each = each == null && column.startsWith(c.name() + ".") ? c : each;
            } else if (column.equals(c.column(null)) || (c.over() == null && values.containsKey(c.name())
                    && column.equals("report." + c.name()))) {
                return c;
            }
        }
        return each;
    }
}
