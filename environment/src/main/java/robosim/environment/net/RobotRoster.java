package robosim.environment.net;

import robosim.environment.run.LoopEvent;
import robosim.environment.run.SimulationLoop;
import robosim.protocol.Printable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.environment.core.JoinRule;
import robosim.environment.core.WorldSpec;
import robosim.protocol.RobotProperties;

/**
 * The control port's changes to a running simulation's robots, {@code add} and {@code remove}: each is an
 * event for the {@link SimulationLoop}, whose answer the caller waits for (a few seconds at most).
 */
public final class RobotRoster {
    /** How long a caller waits for the loop's answer, ms. */
    private static final long ANSWER_MS = 5_000;

    private final SimulationLoop loop;
    /** Starts robots in the Environment's JVM, or null when it runs none there. */
    private final InMemoryTransport inMemory;

    RobotRoster(SimulationLoop loop, InMemoryTransport inMemory) {
        this.loop = loop;
        this.inMemory = inMemory;
    }

    /**
     * Lets robot {@code name}, a {@code type} (a known model), join the running world at (x, y) m heading
     * {@code headingDeg}: the next hello with that name takes part from the next step, at that pose.
     * Returns null, or why not (a name in use, a pose taken or outside the arena, an unknown type).
     */
    public String add(String name, String type, double xM, double yM, double headingDeg, String control)
            throws InterruptedException {
        JoinRule rule;
        try {
            rule = rule(name, type, xM, yM, headingDeg, control);
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
        CompletableFuture<String> verdict = new CompletableFuture<>();
        loop.post(new LoopEvent.AddRobot(rule, verdict));
        return answer(verdict);
    }

    /**
     * The rule by which robot {@code name}, a {@code type} (a known model), joins at (x, y) m heading
     * {@code headingDeg}, once.
     *
     * @throws IllegalArgumentException why there is none (an unknown type, a bad name, a pose that is no number)
     */
    public static JoinRule rule(String name, String type, double xM, double yM, double headingDeg, String control) {
        RobotProperties model = robosim.devices.RobotTypes.properties(type);
        if (model == null) {
            throw new IllegalArgumentException("type \"" + Printable.of(type, 64) + "\" is not a known robot type "
                    + "(known: " + robosim.devices.RobotTypes.names() + "; a RobotType class needs a <join> rule with its radius in the "
                    + "file)");
        }
        if (JoinRule.badName(name) != null) {
            throw new IllegalArgumentException(JoinRule.badName(name));
        }
        if (!Double.isFinite(xM) || !Double.isFinite(yM) || !Double.isFinite(headingDeg)) {
            throw new IllegalArgumentException("the pose must be finite numbers, got " + xM + " " + yM + " "
                    + headingDeg);
        }
        WorldSpec.RobotSpec robot = new WorldSpec.RobotSpec(name, type, control == null ? "" : control, xM * 1000,
                yM * 1000, robosim.geometry.Kinematics.turn(headingDeg, 0));
        return new JoinRule(name, robot, null, 1);
    }

    /**
     * A one-JVM run: starts robot {@code name} (just added) in this JVM with its control class and waits for the
     * loop to welcome it. Returns null, or why it did not start or was refused.
     */
    public String startHere(String name, String type, String control) throws InterruptedException {
        if (inMemory == null) {
            return "this Environment runs no robots in its JVM";
        }
        try {
            return answer(inMemory.start(name, type, control));
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
    }

    /**
     * Removes robot {@code name} from the run for good, whatever {@code --on-robot-loss} says: it is told the
     * simulation is over for it, and stands no more in the world from the end of the step in progress; a robot
     * added and not joined yet is no longer let in. Returns null, or why not (no such robot, already gone).
     */
    public String remove(String name) throws InterruptedException {
        CompletableFuture<String> verdict = new CompletableFuture<>();
        loop.post(new LoopEvent.RemoveRobot(name, verdict));
        return answer(verdict);
    }

    private static String answer(CompletableFuture<String> verdict) throws InterruptedException {
        try {
            return verdict.get(ANSWER_MS, TimeUnit.MILLISECONDS);
        } catch (java.util.concurrent.TimeoutException | java.util.concurrent.ExecutionException e) {
            return "the simulation loop did not answer";
        }
    }
}
