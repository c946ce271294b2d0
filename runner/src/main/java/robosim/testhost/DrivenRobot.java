package robosim.testhost;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.api.RobotControl;
import robosim.devices.RobotType;
import robosim.devices.RobotTypes;

/**
 * The control code of a robot driven from the simulation link ({@code control="ros2"}: the ROS 2 bridge, Python's
 * {@code robosim.ros2}): through the same robot API as any control code, each step it takes the step's command (a
 * velocity and a rotational velocity, as ROS's {@code geometry_msgs/Twist} gives them), held to its type's limits,
 * drives its wheels by it for one step, and leaves what the robot then senses ({@link State}) for the link. The link
 * gives a command before it runs the step (the robot waits for it: the step waits for the robot) and takes the state
 * after; one of each is in hand at a time.
 */
final class DrivenRobot implements RobotControl {
    /** The most messages a step's state carries; more wait for the next step (none is lost). */
    static final int MAX_MESSAGES = 256;

    /** What the robot sensed after the step of command {@code command}: its sonar, every sensor's reading, messages come. */
    record State(long command, double[] sonarMm, Map<String, double[]> readings, List<Message> received) {
    }

    /** A command: its number (the first 1) and the wheels' speeds, mm/s. */
    private record Wheels(long number, double left, double right) {
    }

    private final String name;
    private final List<robosim.devices.DeviceSpec> sensors;
    private final double topMmPerS;
    private final double topDegPerS;
    private final double wheelBaseMm;
    private final BlockingQueue<Wheels> commands = new ArrayBlockingQueue<>(1);
    /** The commands given so far (the link's thread alone). */
    private long given;
    private final BlockingQueue<State> states = new ArrayBlockingQueue<>(1);

    /** Robot {@code name} of type {@code type} (a registered type's name) with {@code sensors}, as its file gives them. */
    DrivenRobot(String name, String type, List<robosim.devices.DeviceSpec> sensors) {
        RobotType t = RobotTypes.known(type);
        this.name = name;
        this.sensors = List.copyOf(sensors);
        this.topMmPerS = t.properties().maxSpeedMmPerS();
        this.topDegPerS = t.properties().maxTurnDegPerS();
        this.wheelBaseMm = t.body().wheelBaseMm();
    }

    String name() {
        return name;
    }

    /** Its sensors, as its file gives them (a proximity sensor's model turns its readings into ranges). */
    List<robosim.devices.DeviceSpec> sensors() {
        return sensors;
    }

    /**
     * The next step's command: {@code mmPerS} ahead (negative: back) and {@code degPerS} counter-clockwise, finite
     * (the link checks). Held to the type's limits: the turn first, then the speed its wheels have left.
     *
     * @throws IllegalStateException if the last command is not taken yet (a step was not run after it)
     */
    void command(double mmPerS, double degPerS) {
        double turn = Math.max(-topDegPerS, Math.min(topDegPerS, degPerS));
        double spin = Math.toRadians(Math.abs(turn)) * wheelBaseMm / 2; // (each wheel's share of the turn, mm/s)
        if (spin > topMmPerS) {
            turn = Math.copySign(Math.toDegrees(topMmPerS * 2 / wheelBaseMm), turn);
            spin = topMmPerS;
        }
        double ahead = Math.max(-(topMmPerS - spin), Math.min(topMmPerS - spin, mmPerS));
        double w = Math.toRadians(turn) * wheelBaseMm / 2;
        double left = Math.max(-topMmPerS, Math.min(topMmPerS, ahead - w)); // (a rounding past the top held to it)
        double right = Math.max(-topMmPerS, Math.min(topMmPerS, ahead + w));
        if (!commands.offer(new Wheels(given + 1, left, right))) {
            throw new IllegalStateException(name + " has a command not yet taken");
        }
        given++;
    }

    /** Takes back a command not yet taken (its step did not run); nothing if it was taken. */
    void withdraw() {
        commands.clear();
    }

    /**
     * The state after the step of the last command, waiting up to {@code ms} for it; null if it did not come (a
     * state of an earlier command, late, is passed over).
     */
    State state(long ms) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ms);
        for (State s = states.poll(ms, TimeUnit.MILLISECONDS); s != null;
                s = states.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS)) {
            if (s.command() == given) {
                return s;
            }
        }
        return null;
    }

    @Override
    public void run(Robot robot) throws InterruptedException {
        List<String> sensors = robot.sensorNames();
        while (true) {
            Wheels wheels = commands.take();
            robot.setWheelSpeeds(wheels.left(), wheels.right());
            robot.step();
            Map<String, double[]> readings = new LinkedHashMap<>();
            for (String s : sensors) {
                readings.put(s, robot.sensor(s));
            }
            List<Message> received = new ArrayList<>();
            for (Message m = received.size() < MAX_MESSAGES ? robot.receive() : null; m != null;
                    m = received.size() < MAX_MESSAGES ? robot.receive() : null) {
                received.add(m);
            }
            states.clear(); // (a state the link gave up waiting for is stale: the newest is the one it wants)
            states.offer(new State(wheels.number(), robot.sonarRanges(), readings, received));
        }
    }
}
