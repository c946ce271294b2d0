package robosim.hardware;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.api.RobotControl;
import robosim.protocol.CommEvent;

/** What the robot API refuses at once, what it queues for the next step, and the time step it reports. */
class SimulatedRobotTest {
    @Test
    void stepMsIsTheTimeStepOfTheEnvironmentsWelcome() throws Exception {
        long[] seen = new long[2];
        RobotControl control = robot -> {
            seen[0] = robot.stepMs();
            robot.sleep(1);
            seen[1] = robot.stepMs();
        };
        ScriptedEnvironment.run(control, 125, 3);
        assertArrayEquals(new long[] {125, 125}, seen, "before the first step and after it");
        RobotKnowledge state = new RobotKnowledge("r1", new Scout());
        assertEquals(40, new SimulatedRobot(state, new ControlLink(), List.of("r1"), 40, List.of()).stepMs());
    }

    @Test
    void sendQueuesBroadcastAddressesEveryoneAndOversizedTextIsRefusedAtOnce() {
        RobotKnowledge state = new RobotKnowledge("r1", new ArRobot());
        SimulatedRobot robot = new SimulatedRobot(state, new ControlLink(), List.of("r1", "r2"), 500, List.of());
        robot.send("r2", "hi");
        robot.broadcast("all");
        assertEquals(List.of(new CommEvent("r1", "r2", "hi"), new CommEvent("r1", CommEvent.EVERYONE, "all")),
                state.takeOutbox());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> robot.send("r2", "x".repeat(70_000)));
        assertTrue(e.getMessage().startsWith("a message of 70000 bytes is more than the wire's limit of 65535"),
                e.getMessage());
        assertEquals(List.of(), state.takeOutbox(), "nothing half-sent");
    }
}
