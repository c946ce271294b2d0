package robosim.api;

import java.util.List;

/**
 * A robot as its control code sees it. Blocking calls ({@link #move}, {@link #turn}, {@link #sleep},
 * {@link #waitForMessage}) return when the robot has done them; the others answer at once from the
 * robot's newest readings.
 */
public interface Robot {
    /** This robot's name. */
    String name();

    /** The names of every robot in the world, this one included. */
    List<String> robotNames();

    /**
     * Drives {@code mm} along the heading (negative: backwards) at the set velocity; returns the
     * distance actually covered, which is shorter when the robot touched something.
     */
    double move(double mm) throws InterruptedException;

    /** Turns in place by {@code deg} (positive: counter-clockwise); returns the angle turned. */
    double turn(double deg) throws InterruptedException;

    /** Sets the speed for {@link #move}, mm/s (limited to the robot's maximum). */
    void setVelocity(double mmPerS);

    double velocity();

    /** Sets the rate for {@link #turn}, deg/s (limited to the robot's maximum). */
    void setRotVelocity(double degPerS);

    double rotVelocity();

    /**
     * Tags the nearest robot or taggable object in front, within the world's tag range; takes one
     * step. Returns its name, or "" when nothing was in reach.
     */
    String tag() throws InterruptedException;

    /** Waits {@code ms} of robot time, standing still. */
    void sleep(long ms) throws InterruptedException;

    /** The newest sonar ranges, mm, one per transducer in {@link #sonarAnglesDeg()} order. */
    double[] sonarRanges();

    /** Direction of each sonar, degrees from the heading. */
    double[] sonarAnglesDeg();

    /** The names of this robot's other sensors (laser, heat, bump, ... as the world configures them). */
    List<String> sensorNames();

    /**
     * The newest reading of the sensor of that name, in its own units and order (a laser: ranges in mm
     * from right to left; heat: one value; bump: front, left, back, right as 1 or 0); empty before the
     * first step. An unknown name is an IllegalArgumentException.
     */
    double[] sensor(String name);

    /** Odometry: position, mm. */
    double xMm();

    double yMm();

    /** Odometry: heading, degrees in [0, 360). */
    double headingDeg();

    /** What the robot touched during its last move or turn, or "" if nothing. */
    String lastContact();

    /**
     * Sends a text message to the robot named {@code to}; it goes out with the robot's next step.
     * Text longer than the wire allows (65,535 bytes as UTF-8) is refused here at once; the world's
     * own, smaller limit and unknown recipients are reported back by the simulator.
     */
    void send(String to, String text);

    /** Sends a text message to every other robot (within communication range, if the world has one). */
    void broadcast(String text);

    /** The oldest message not yet received, or null if there is none. */
    Message receive();

    /** Waits up to {@code timeoutMs} of robot time for a message; null if none came. */
    Message waitForMessage(long timeoutMs) throws InterruptedException;
}
