package robosim.devices;

import java.util.List;

/**
 * What a sensor may ask about the world, aimed at one robot at a time, on the world after every move of the step:
 * the robot's pose and radius, rays, lines of sight, heat sources, what it touches, the ranges the Geometry process
 * measured for it (a sensor it computes), and the world's one seeded generator for noise. Positions are world
 * millimetres, angles degrees counter-clockwise from +x. Reused from robot to robot: a sensor does not keep it.
 */
public interface SensorContext {
    /** The robot it is aimed at (world order). */
    int robot();

    double xMm();

    double yMm();

    double headingDeg();

    double radiusMm();

    /** Distance from the robot's centre along a world angle to the first wall, obstacle or other robot, capped. */
    double ray(double worldAngleDeg, double maxMm);

    /** True when no obstacle stands on the straight line from the robot's centre to the point. */
    boolean clearTo(double xMm, double yMm);

    /** The world's heat sources. */
    List<HeatSource> heatSources();

    /** World directions (degrees) to everything within {@code toleranceMm} of the robot's rim, into {@code out}; how many. */
    int touching(double toleranceMm, double[] out);

    /** The range the Geometry process measured along the robot's sonar {@code sonar} this step, mm. */
    double sonarRange(int sonar);

    /**
     * The next Gaussian (mean 0, deviation 1) of the world's one seeded generator: the only source of a sensor's
     * noise, drawn in robot order and, for a robot, in the order its sensors are read, so a run repeats bit for bit.
     */
    double gaussian();
}
