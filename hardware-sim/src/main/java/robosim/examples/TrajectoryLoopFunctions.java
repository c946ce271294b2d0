package robosim.examples;

import java.util.ArrayList;
import java.util.List;
import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;

/**
 * ARGoS's trajectory_loop_functions (examples/argos/trajectory.xml): each robot's waypoints, its start and then each
 * place it has reached more than {@code min_distance} (m; ARGoS's 0.05) from its last; each waypoint is drawn for the
 * viewers as the robot's trace (ARGoS's trajectory_qtuser_functions draw them in its window), in the robot's own
 * colour; a run long enough to fill a drawing ({@code Traces.MAX_POINTS}) has each path's newer half drawn again, its
 * waypoints all kept. A reset starts every path afresh where the robots stand.
 */
public final class TrajectoryLoopFunctions implements LoopFunctions {
    /** A colour a robot, in world order, from ten (Matplotlib's default cycle, distinct on a light floor). */
    private static final int[] COLOURS = {0x1F77B4, 0xFF7F0E, 0x2CA02C, 0xD62728, 0x9467BD, 0x8C564B, 0xE377C2,
        0x7F7F7F, 0xBCBD22, 0x17BECF};

    private double minSquaredMm;
    /** Each robot's waypoints, x and y (mm) in turn. */
    private final List<List<double[]>> waypoints = new ArrayList<>();
    /** Points drawn since the drawing was last erased. */
    private int drawn;

    @Override
    public void init(Experiment world) {
        double min = world.parameter("min_distance", 0.05) * 1000;
        if (!(min > 0)) {
            throw new IllegalArgumentException("min_distance is a length > 0 m, got " + min / 1000);
        }
        minSquaredMm = min * min;
        waypoints.clear();
        world.eraseTraces();
        drawn = 0;
        for (int r = 0; r < world.robots(); r++) {
            start(world, r);
        }
    }

    private void start(Experiment world, int r) {
        List<double[]> path = new ArrayList<>();
        waypoints.add(path);
        add(world, r, path);
    }

    private void add(Experiment world, int r, List<double[]> path) {
        double[] p = {world.robotXMm(r), world.robotYMm(r)};
        path.add(p);
        if (drawn == robosim.protocol.Traces.MAX_POINTS) { // (a drawing's bound: each path's newer half drawn again)
            world.eraseTraces();
            drawn = 0;
            int keep = robosim.protocol.Traces.MAX_POINTS / 2 / waypoints.size();
            for (int k = 0; k < waypoints.size(); k++) {
                List<double[]> w = waypoints.get(k);
                for (double[] q : w.subList(Math.max(0, w.size() - keep - (k == r ? 1 : 0)),
                        w.size() - (k == r ? 1 : 0))) {
                    draw(world, k, q);
                }
            }
        }
        draw(world, r, p);
    }

    private void draw(Experiment world, int r, double[] p) {
        world.trace(world.robotName(r), p[0], p[1], COLOURS[r % COLOURS.length]);
        drawn++;
    }

    @Override
    public void postStep(Experiment world) {
        for (int r = 0; r < world.robots(); r++) {
            if (r == waypoints.size()) { // (a robot that joined)
                start(world, r);
                continue;
            }
            List<double[]> path = waypoints.get(r);
            double[] last = path.get(path.size() - 1);
            double dx = world.robotXMm(r) - last[0];
            double dy = world.robotYMm(r) - last[1];
            if (world.present(r) && dx * dx + dy * dy > minSquaredMm) {
                add(world, r, path);
            }
        }
    }

    /** Robot {@code r}'s waypoints so far, x and y (mm) each. */
    public List<double[]> waypoints(int r) {
        return List.copyOf(waypoints.get(r));
    }
}
