package robosim.environment.net;

import robosim.protocol.Printable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.environment.core.JoinRule;
import robosim.environment.core.WorldSpec;
import robosim.protocol.RobotModels;
import robosim.protocol.RobotProperties;

/**
 * The control port's changes to a running simulation's robots, {@code add} and {@code remove}: each is an
 * event for the {@link SimulationLoop}, whose answer the caller waits for (a few seconds at most).
 */
public final class RobotRoster {
    /** How long a caller waits for the loop's answer, ms. */
    private static final long ANSWER_MS = 5_000;

    private final ClientWorkerCoordinator coordinator;

    RobotRoster(ClientWorkerCoordinator coordinator) {
        this.coordinator = coordinator;
    }

    /**
     * Lets robot {@code name}, a {@code type} (a known model), join the running world at (x, y) m heading
     * {@code headingDeg}: the next hello with that name takes part from the next step, at that pose.
     * Returns null, or why not (a name in use, a pose taken or outside the arena, an unknown type).
     */
    public String add(String name, String type, double xM, double yM, double headingDeg, String control)
            throws InterruptedException {
        RobotProperties model = RobotModels.byName(type);
        if (model == null) {
            return "type \"" + Printable.of(type, 64) + "\" is not a known robot type (known: " + RobotModels.names()
                    + "; a RobotType class needs a <join> rule with its radius in the file)";
        }
        if (JoinRule.badName(name) != null) {
            return JoinRule.badName(name);
        }
        if (!Double.isFinite(xM) || !Double.isFinite(yM) || !Double.isFinite(headingDeg)) {
            return "the pose must be finite numbers, got " + xM + " " + yM + " " + headingDeg;
        }
        WorldSpec.RobotSpec robot = new WorldSpec.RobotSpec(name, type, control == null ? "" : control, xM * 1000,
                yM * 1000, robosim.geometry.Kinematics.turn(headingDeg, 0));
        CompletableFuture<String> verdict = new CompletableFuture<>();
        coordinator.post(new LoopEvent.AddRobot(new JoinRule(name, robot, null, 1), verdict));
        return answer(verdict);
    }

    /**
     * A one-JVM run: starts robot {@code name} (just added) in this JVM with its control class and waits for the
     * loop to welcome it. Returns null, or why it did not start or was refused.
     */
    public String startHere(String name, String type, String control) throws InterruptedException {
        try {
            return answer(coordinator.helloInMemory(name, type, control));
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
        coordinator.post(new LoopEvent.RemoveRobot(name, verdict));
        return answer(verdict);
    }

    private static String answer(CompletableFuture<String> verdict) throws InterruptedException {
        String why = ClientWorkerCoordinator.await(verdict, ANSWER_MS, TimeUnit.MILLISECONDS);
        return why == null && !verdict.isDone() ? "the simulation loop did not answer" : why;
    }
}
