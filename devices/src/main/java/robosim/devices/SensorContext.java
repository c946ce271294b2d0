package robosim.devices;

import java.util.List;
import robosim.protocol.Light;

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

    /** The range the Geometry process measured along the robot's proximity ray {@code ray} this step, mm. */
    double rayRange(int ray);

    /** The floor's colour at world point (x, y), {@code 0xRRGGBB}. */
    int floorColour(double xMm, double yMm);

    /** The world's lights. */
    List<Light> lights();

    /**
     * True when the straight line from the robot's centre, {@code fromZMm} over the floor, to the point (x, y)
     * {@code zMm} over the floor passes nothing as tall as the line where it passes: no obstacle, no object or robot
     * taller there (the robot itself and robot {@code other}, -1 for none, aside).
     */
    boolean sight(double fromZMm, double xMm, double yMm, double zMm, int other);

    /**
     * Every lit LED of the other robots whose centre lies within {@code rangeMm} of this robot's, to {@code visitor}
     * (which robot, where the LED is in the world, its colour), the robots in world order. Found through an index of
     * the step's LEDs made once a step, whichever robot asks first.
     */
    void leds(double rangeMm, LedVisitor visitor);

    /** What {@link #leds} tells of each lit LED. */
    interface LedVisitor {
        void led(int robot, double xMm, double yMm, double zMm, int rgb);
    }

    /**
     * The range-and-bearing messages the robot received this step, nearest first, as many as its sensor reads (worked
     * out for it when it first asks in a step).
     */
    List<RabMessage> rabReceived();

    /**
     * The next Gaussian (mean 0, deviation 1) of the world's one seeded generator: the only source of a sensor's
     * noise, drawn in robot order and, for a robot, in the order its sensors are read, so a run repeats bit for bit.
     */
    double gaussian();
}
