package robosim.environment.metrics;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.ServiceLoader;

/**
 * The built-in metrics: every {@link StepMetric} registered for {@link ServiceLoader} on the class path, in column
 * order (their {@link MetricInfo#column()}, then their names). What reads the built-in metrics reads them here: a
 * sweep's columns, tables and plots, {@code record-tool.sh metrics}, a run's live tally, the testkit, the learning
 * link's metrics array and {@code describe.sh metrics}. Any thread.
 */
public final class Metrics {
    /** Each built-in metric's provider (a new instance a call) and what it is, in column order. */
    private static final List<Registered> REGISTERED = load();
    private static final List<MetricInfo> BUILT_IN = REGISTERED.stream().map(Registered::info).toList();

    private record Registered(ServiceLoader.Provider<StepMetric> provider, MetricInfo info) {
    }

    private Metrics() {
    }

    /** Every built-in metric, in column order. */
    public static List<MetricInfo> builtIn() {
        return BUILT_IN;
    }

    /** Their names, in column order. */
    public static List<String> names() {
        return BUILT_IN.stream().map(MetricInfo::name).toList();
    }

    /** The built-in metric named {@code name}, or null. */
    public static MetricInfo info(String name) {
        for (MetricInfo m : BUILT_IN) {
            if (m.name().equals(name)) {
                return m;
            }
        }
        return null;
    }

    /** A new instance of every built-in metric, in column order: a run's tally. */
    public static List<StepMetric> fresh() {
        return REGISTERED.stream().map(r -> r.provider().get()).toList();
    }

    private static List<Registered> load() {
        List<Registered> all = new ArrayList<>();
        for (ServiceLoader.Provider<StepMetric> p : ServiceLoader.load(StepMetric.class, Metrics.class.getClassLoader())
                .stream().toList()) {
            all.add(new Registered(p, p.get().info()));
        }
        all.sort(Comparator.comparingInt((Registered r) -> r.info().column()).thenComparing(r -> r.info().name()));
        for (int i = 1; i < all.size(); i++) {
            String name = all.get(i).info().name();
            if (name.equals(all.get(i - 1).info().name())) {
                throw new IllegalStateException("two built-in metrics are named " + name + ": "
                        + all.get(i - 1).provider().type().getName() + " and "
                        + all.get(i).provider().type().getName());
            }
        }
        return List.copyOf(all);
    }
}
