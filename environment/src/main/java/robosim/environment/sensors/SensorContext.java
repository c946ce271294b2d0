package robosim.environment.sensors;

import java.util.List;
import robosim.environment.core.WorldSpec.HeatSource;
import robosim.geometry.WorldQueries;

/**
 * What a sensor may ask about the world, aimed at one robot at a time: its pose and radius, rays,
 * lines of sight, heat sources, and what it touches. Positions are world millimetres at the end of
 * the step; angles degrees counter-clockwise from +x. Reused from robot to robot: do not keep it.
 */
public final class SensorContext {
    private final WorldQueries queries;
    private final List<HeatSource> heatSources;
    private final double[] x;
    private final double[] y;
    private final double[] radius;
    private final double[] heading;
    private int robot;

    public SensorContext(WorldQueries queries, List<HeatSource> heatSources, double[] x, double[] y,
            double[] radius, double[] heading) {
        this.queries = queries;
        this.heatSources = List.copyOf(heatSources);
        this.x = x;
        this.y = y;
        this.radius = radius;
        this.heading = heading;
    }

    /** Aims the context at robot {@code i}. */
    public SensorContext aim(int i) {
        robot = i;
        return this;
    }

    public int robot() {
        return robot;
    }

    public double xMm() {
        return x[robot];
    }

    public double yMm() {
        return y[robot];
    }

    public double headingDeg() {
        return heading[robot];
    }

    public double radiusMm() {
        return radius[robot];
    }

    /** Distance from the robot's centre along a world angle to the first wall or other robot, capped. */
    public double ray(double worldAngleDeg, double maxMm) {
        return queries.ray(x[robot], y[robot], worldAngleDeg, maxMm, x, y, radius, robot);
    }

    /** True when no obstacle stands on the straight line from the robot's centre to the point. */
    public boolean clearTo(double xMm, double yMm) {
        return queries.clear(x[robot], y[robot], xMm, yMm);
    }

    public List<HeatSource> heatSources() {
        return heatSources;
    }

    /** World directions (degrees) to everything within {@code toleranceMm} of the robot's rim; how many. */
    public int touching(double toleranceMm, double[] out) {
        return queries.touching(robot, x, y, radius, toleranceMm, out);
    }
}
