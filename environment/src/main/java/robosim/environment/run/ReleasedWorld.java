package robosim.environment.run;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.environment.core.EnvironmentMap;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.environment.metrics.MetricTally;
import robosim.environment.metrics.Metrics;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;
import robosim.protocol.WorldSnapshot;

/**
 * The world as the run last released it, one immutable object published after each release: how many steps have
 * gone out, the world's robots (those that joined included) and what each is, and every robot's pose after the
 * step with the step's sonar ranges, the tags so far and who has left or is away ({@link PoseUpdate}), and the run's
 * built-in metrics so far (in the registry's column order, {@link Metrics}). The status,
 * the control port's queries, a viewer that joins and the recording read this, never the core's map, which moves
 * on as soon as the next step is computed (a step held at the release point is computed already). Any thread.
 */
public final class ReleasedWorld {
    private final long steps;
    private final WorldSpec spec;
    private final List<RobotProperties> properties;
    private final PoseUpdate update;
    private final boolean grown;
    private final double[] metrics;
    private static final double[] NO_METRICS = new double[0];

    private ReleasedWorld(long steps, WorldSpec spec, List<RobotProperties> properties, PoseUpdate update,
            boolean grown, double[] metrics) {
        this.steps = steps;
        this.spec = spec;
        this.properties = properties;
        this.update = update;
        this.grown = grown;
        this.metrics = metrics;
    }

    /**
     * Before the start: every robot of the file at its start pose, as it said it is in its hello
     * ({@code said[i]}), or, not connected yet, as the file expects it (its model, or a disc of the file's radius).
     */
    static ReleasedWorld expected(WorldSpec spec, RobotProperties[] said) {
        int n = spec.robots().size();
        List<RobotProperties> props = new ArrayList<>(n);
        double[] x = new double[n];
        double[] y = new double[n];
        double[] h = new double[n];
        for (int i = 0; i < n; i++) {
            WorldSpec.RobotSpec r = spec.robots().get(i);
            RobotProperties model = robosim.devices.RobotTypes.properties(r.type());
            props.add(said[i] != null ? said[i] : model != null ? model
                    : new RobotProperties(r.type(), r.radiusMm(), 1, 1, List.of()));
            x[i] = r.xMm();
            y[i] = r.yMm();
            h[i] = r.headingDeg();
        }
        return new ReleasedWorld(0, spec, List.copyOf(props), new PoseUpdate(-1, x, y, h), false, new double[0]);
    }

    /**
     * The world as the run starts from it: no step out yet, every robot and object where {@code core}'s map has it, the
     * floor, lights and objects as the loop functions' init left them ({@link SimulationCore#startUpdate}).
     */
    static ReleasedWorld start(SimulationCore core) {
        EnvironmentMap map = core.map();
        return new ReleasedWorld(0, map.spec(), map.properties(), core.startUpdate(), false, values(core.metrics()));
    }

    /** The world after {@code core}'s last step, the {@code steps}-th out; grown if robots joined since this one. */
    ReleasedWorld next(long stepsOut, SimulationCore core) {
        EnvironmentMap map = core.map();
        return new ReleasedWorld(stepsOut, map.spec(), map.properties(), core.viewerUpdate(),
                map.robotCount() != update.count(), values(core.metrics()));
    }

    private static double[] values(MetricTally tally) {
        if (tally == null) {
            return NO_METRICS;
        }
        double[] v = new double[tally.size()];
        for (int i = 0; i < v.length; i++) {
            v[i] = tally.value(i);
        }
        return v;
    }

    /** The run's built-in metrics so far, by name in column order (none before the run has started). */
    public Map<String, Double> metrics() {
        Map<String, Double> out = new LinkedHashMap<>();
        List<String> names = Metrics.names();
        for (int i = 0; i < metrics.length; i++) {
            out.put(names.get(i), metrics[i]);
        }
        return out;
    }

    /** Steps whose responses have gone out. */
    long steps() {
        return steps;
    }

    /** Every robot's pose after the last step out, its sonar ranges, the tags so far, who has left or is away. */
    PoseUpdate update() {
        return update;
    }

    /** True if robots joined the world since the world released before this one: viewers need its snapshot. */
    boolean grown() {
        return grown;
    }

    /** Robots in the world, those that left included. */
    int robots() {
        return update.count();
    }

    /** Robot {@code i}'s name (world order). */
    String name(int i) {
        return spec.robots().get(i).name();
    }

    /** A viewer's whole picture of this world: the static world, every robot and its pose (no sonar ranges, no tags). */
    WorldSnapshot snapshot() {
        return EnvironmentMap.snapshot(spec, properties, update.posesOnly());
    }
}
