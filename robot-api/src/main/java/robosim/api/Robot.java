package robosim.api;

import java.util.List;

/**
 * A robot as its control code sees it. Blocking calls ({@link #move}, {@link #turn}, {@link #tag},
 * {@link #sleep}, {@link #waitForMessage}) return when the robot has done them; the others answer at
 * once from the robot's newest readings.
 *
 * <p>Robot time advances in whole time steps of {@link #stepMs()}; every blocking call takes a whole
 * number of steps (in the simulator robot time also stands still while control code computes between
 * calls). Units: millimetres, degrees (counter-clockwise), milliseconds. Per robot type (sonar
 * mounting, cone width, range, radius, speed limits) and the exact rounding rules:
 * {@code hardware-sim/README.md}, sections "Robot types" and "How a call becomes steps".
 */
public interface Robot {
    /** This robot's name. */
    String name();

    /**
     * The simulation's time step, ms: the robot time one step takes, the same for every robot of the
     * world and fixed for the whole run (a simulator takes it from its world; a real robot from its
     * control cycle).
     */
    long stepMs();

    /** The names of every robot in the world, this one included. */
    List<String> robotNames();

    /**
     * Drives {@code mm} along the heading (negative: backwards) at the set velocity; returns the
     * distance actually covered, which is shorter when the robot touched something. Takes one step per
     * piece of at most {@code velocity() * stepMs() / 1000} mm; a shorter last piece still takes a
     * whole step (step 500 ms, 500 mm/s: {@code move(600)} is 250 + 250 + 100 mm in three steps).
     * {@code move(0)} returns 0 at once, without a step.
     */
    double move(double mm) throws InterruptedException;

    /**
     * Turns in place by {@code deg} (positive: counter-clockwise); returns the angle turned. Cut into
     * steps like {@link #move}, pieces of at most {@code rotVelocity() * stepMs() / 1000} degrees.
     */
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

    /**
     * Waits {@code ms} of robot time, standing still, rounded up to whole steps and at least one step:
     * with 500 ms steps {@code sleep(0)} and {@code sleep(500)} take one step, {@code sleep(501)} two.
     */
    void sleep(long ms) throws InterruptedException;

    /**
     * The newest sonar ranges, mm, one per transducer in {@link #sonarAnglesDeg()} order, measured from
     * the transducer on the rim; the sonar's maximum range when nothing is in its cone, NaN before the
     * first step.
     */
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

    /**
     * Returns the oldest waiting message at once, if there is one; otherwise waits for one, standing
     * still, up to {@code timeoutMs} rounded up to whole steps (at least one step), and ends with the
     * step in which a message arrives. Null if none came.
     */
    Message waitForMessage(long timeoutMs) throws InterruptedException;

    /**
     * A seed for this robot's own random numbers ({@code new Random(robot.seed())}): made from the run's seed (the
     * environment file's {@code seed}, or the one a sweep or {@code --seed} gives) and this robot's name, so robots
     * of one run differ, and a run with the same seed repeats. (A driver without a run seed: its name's hash.)
     */
    default long seed() {
        return name().hashCode();
    }

    /**
     * The value of the parameter {@code name} the environment file gives this robot ({@code <param name= value=>}
     * on the robot, else on the world; a sweep may set it), or {@code defaultValue} when it gives none (a driver
     * without parameters: always).
     */
    default String parameter(String name, String defaultValue) {
        return defaultValue;
    }

    /**
     * As {@link #parameter(String, String)}, read as a number; a value that is not a number is an
     * IllegalArgumentException naming the parameter and the value.
     */
    default double parameter(String name, double defaultValue) {
        String value = parameter(name, (String) null);
        if (value == null) {
            return defaultValue;
        }
        try {
            return Double.parseDouble(value.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("parameter " + name + " is '" + value + "', not a number");
        }
    }

    /**
     * Reports a value of this run (items found, the step a goal was reached...): it goes out with the robot's next
     * step and is recorded with the run; the newest value of each name counts, and a sweep's table sums each name
     * over the robots ({@code docs/EXPERIMENTS.md}). A name is 1 to 64 letters, digits, {@code _ . -}; the value a
     * finite number; anything else, or more than 64 names in one step, is an IllegalArgumentException at once. (A
     * driver that records nothing: does nothing.)
     */
    default void report(String name, double value) {
    }

    // ---- what a robot type may carry besides: wheels, LEDs, a gripper, range and bearing, other actuators -------
    // (each a default method: a robot without the device says so, so a real robot's driver written before compiles)

    /**
     * Drives on its wheels: sets the left and the right wheel's speed, mm/s (positive: forward), held until set again.
     * Time passes with the wheels at these speeds in {@link #step}, {@link #sleep} and {@link #waitForMessage} (standing
     * still at 0 and 0, as a robot starts); {@link #move} and {@link #turn} drive by their own velocities while they
     * run. A differential drive: each step turns by {@code (right - left) / wheel base} radians a second, then moves
     * {@code (left + right) / 2}, times the step. A speed beyond the robot's top speed, or not a number, or a pair
     * that turns faster than its top turn rate, is an IllegalArgumentException naming them.
     */
    default void setWheelSpeeds(double leftMmPerS, double rightMmPerS) {
        throw new UnsupportedOperationException(name() + " cannot set its wheels' speeds");
    }

    /** One time step passes, the robot driving on its wheels as set ({@link #setWheelSpeeds}; standing still at 0). */
    default void step() throws InterruptedException {
        sleep(stepMs());
    }

    /** The names of this robot's actuators ({@code leds}, {@code rab}, ...: its type's). */
    default List<String> actuatorNames() {
        return List.of();
    }

    /**
     * Sets the actuator named {@code name} to {@code values} from the next step on, until set again (each actuator's
     * values: {@code describe.sh NAME}). An unknown name, or values it cannot take (their count, their range), is an
     * IllegalArgumentException naming them.
     */
    default void actuate(String name, double... values) {
        throw new IllegalArgumentException("no actuator named " + name + " on " + name());
    }

    /** How many LEDs it has (0: none). */
    default int ledCount() {
        return 0;
    }

    /** Sets every LED to colour {@code rgb} ({@code 0xRRGGBB}, {@link Colours}; {@code Colours.BLACK} is off). */
    default void setLeds(int rgb) {
        double[] all = new double[ledCount()];
        java.util.Arrays.fill(all, rgb);
        actuate("leds", all);
    }

    /** Sets LED {@code index} to colour {@code rgb}, the others as they are. */
    default void setLed(int index, int rgb) {
        throw new IllegalArgumentException(name() + " has no LED " + index);
    }

    /**
     * Takes the nearest gripable object touching its front (within its gripper's reach and angle: hardware-sim/README.md);
     * takes one step. Returns the object's name, or "" when nothing was in reach (it then holds nothing). An object
     * held moves and turns with the robot until {@link #release}.
     */
    default String grip() throws InterruptedException {
        throw new UnsupportedOperationException(name() + " has no gripper");
    }

    /** Lets go of what it holds (nothing: nothing happens); takes one step. */
    default void release() throws InterruptedException {
        throw new UnsupportedOperationException(name() + " has no gripper");
    }

    /** The object it holds, or "" for none. */
    default String gripped() {
        return "";
    }

    /**
     * Sets the bytes its range-and-bearing device sends every step from the next on, until set again (each 0 to 255,
     * as many as its messages hold); what it hears is its sensor {@code rab}.
     */
    default void setRabData(int... bytes) {
        double[] values = new double[bytes.length];
        for (int k = 0; k < bytes.length; k++) {
            values[k] = bytes[k];
        }
        actuate("rab", values);
    }
}
