package robosim.examples;

import java.util.ArrayList;
import java.util.List;
import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;

/**
 * ARGoS's custom_distributions_loop_functions (examples/argos/custom_distributions.xml): before step 0 they place the
 * world's robots, in world order, as a cluster, then a scale-free network, then a line. ARGoS's add the robots; a
 * RoboSim world's robots come from its file (or join), so these move the ones the file placed out of the way, each
 * move refused where the robot would overlap something and tried again, as ARGoS's {@code MoveEntity} is:
 * <ul>
 * <li>{@code cluster_robots} robots uniformly at random in the square around {@code cluster_center} (x,y, m) whose
 * area is their footprint over {@code cluster_density}, each at a random heading;
 * <li>{@code scalefree_robots} robots grown as a scale-free network around {@code scalefree_center}: the first there,
 * each next one near a pivot picked with a chance in proportion to its connections, an offset of half
 * {@code scalefree_range} to a whole range away on each axis (ARGoS's adds the centre once more, which is nothing at
 * its file's centre, (0, 0), and here would be the arena's half);
 * <li>{@code line_robots} robots on a diagonal from {@code line_center}, one metre apart along each axis (ARGoS's
 * code places them so, whatever its {@code robot_distance} says).
 * </ul>
 * A robot that cannot be placed in 20 tries (for the scale-free network, 20 pivots of 20 tries each) ends the run,
 * as ARGoS's throws. The draws are the experiment's ({@link Experiment#random()}).
 */
public final class CustomDistributionsLoopFunctions implements LoopFunctions {
    /** A foot-bot's radius, m (ARGoS's FB_RADIUS), and so its footprint. */
    private static final double FB_RADIUS_M = 0.085036758;
    private static final double FB_AREA_M2 = Math.PI * FB_RADIUS_M * FB_RADIUS_M;
    private static final int MAX_PLACE_TRIALS = 20;
    private static final int MAX_ROBOT_TRIALS = 20;

    @Override
    public void init(Experiment world) {
        int next = 0;
        int cluster = (int) world.parameter("cluster_robots", 0);
        next = placeCluster(world, centre(world, "cluster_center"), cluster, world.parameter("cluster_density", 0.1),
                next);
        int free = (int) world.parameter("scalefree_robots", 0);
        next = placeScaleFree(world, centre(world, "scalefree_center"), free, world.parameter("scalefree_range", 1.5),
                next);
        placeLine(world, centre(world, "line_center"), (int) world.parameter("line_robots", 0), next);
    }

    /** Parameter {@code name}, "x,y" in metres, as mm. */
    private static double[] centre(Experiment world, String name) {
        String[] xy = world.parameter(name, "0,0").split(",");
        if (xy.length != 2) {
            throw new IllegalArgumentException(name + " is X,Y in metres, got " + world.parameter(name, ""));
        }
        return new double[] {Double.parseDouble(xy[0].trim()) * 1000, Double.parseDouble(xy[1].trim()) * 1000};
    }

    private static int placeCluster(Experiment world, double[] centre, int robots, double density, int first) {
        double halfSideMm = Math.sqrt(FB_AREA_M2 * robots / density) / 2 * 1000;
        for (int i = first; i < first + robots; i++) {
            boolean done = false;
            for (int trial = 0; !done && trial <= MAX_PLACE_TRIALS; trial++) {
                double x = centre[0] + uniform(world, -halfSideMm, halfSideMm);
                double y = centre[1] + uniform(world, -halfSideMm, halfSideMm);
                done = world.moveRobot(robot(world, i), x, y, uniform(world, 0, 360));
            }
            if (!done) {
                throw new IllegalStateException("cannot place " + world.robotName(i) + " in the cluster");
            }
        }
        return first + robots;
    }

    private static int placeScaleFree(Experiment world, double[] centre, int robots, double rangeM, int first) {
        if (robots == 0) {
            return first;
        }
        double halfRangeMm = rangeM * 500;
        List<double[]> placed = new ArrayList<>(); // x, y and connections of each robot placed
        int total = 0;
        if (!world.moveRobot(robot(world, first), centre[0], centre[1], 0)) {
            throw new IllegalStateException("cannot place " + world.robotName(first) + " at the network's centre");
        }
        placed.add(new double[] {centre[0], centre[1], 1});
        total += 2;
        for (int i = first + 1; i < first + robots; i++) {
            boolean done = false;
            double[] pivot = null;
            for (int robotTrial = 0; !done && robotTrial <= MAX_ROBOT_TRIALS; robotTrial++) {
                pivot = pick(world, placed, total);
                double heading = uniform(world, 0, 360);
                for (int placeTrial = 0; !done && placeTrial <= MAX_PLACE_TRIALS; placeTrial++) {
                    double x = coordinate(world, halfRangeMm) + pivot[0];
                    double y = coordinate(world, halfRangeMm) + pivot[1];
                    done = world.moveRobot(robot(world, i), x, y, heading);
                    if (done) {
                        placed.add(new double[] {x, y, 1});
                    }
                }
            }
            if (!done) {
                throw new IllegalStateException("cannot place " + world.robotName(i) + " in the scale-free network");
            }
            pivot[2]++;
            total += 2;
        }
        return first + robots;
    }

    /** A robot placed before, picked with a chance in proportion to its connections (ARGoS's SFData.Pick). */
    private static double[] pick(Experiment world, List<double[]> placed, int total) {
        if (placed.size() == 1) {
            return placed.get(0);
        }
        int x = world.random().nextInt(total);
        int sum = 0;
        int k = 0;
        while (k < placed.size() && sum <= x) {
            sum += (int) placed.get(k)[2];
            k++;
        }
        return k < placed.size() ? placed.get(k - 1) : placed.get(placed.size() - 1);
    }

    /** An offset of half a range to a whole range, either way (ARGoS's GenerateCoordinate), mm. */
    private static double coordinate(Experiment world, double halfRangeMm) {
        double v = uniform(world, -halfRangeMm, halfRangeMm);
        return v > 0 ? v + halfRangeMm : v - halfRangeMm;
    }

    private static void placeLine(Experiment world, double[] centre, int robots, int first) {
        for (int i = 0; i < robots; i++) {
            if (!world.moveRobot(robot(world, first + i), centre[0] + i * 1000, centre[1] + i * 1000, 0)) {
                throw new IllegalStateException("cannot place " + world.robotName(first + i) + " on the line");
            }
        }
    }

    private static int robot(Experiment world, int i) {
        if (i >= world.robots()) {
            throw new IllegalStateException("the distributions ask for " + (i + 1) + " robots; the world has "
                    + world.robots());
        }
        return i;
    }

    private static double uniform(Experiment world, double min, double max) {
        return min + world.random().nextDouble() * (max - min);
    }
}
