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
        RobotKnowledge state = new RobotKnowledge("r1", new robosim.devices.Scout());
        assertEquals(40, new SimulatedRobot(state, new ControlLink(), List.of("r1"), 40, List.of(), List.of(), 1,
                java.util.Map.of()).stepMs());
    }

    @Test
    void sendQueuesBroadcastAddressesEveryoneAndOversizedTextIsRefusedAtOnce() {
        RobotKnowledge state = new RobotKnowledge("r1", new robosim.devices.ArRobot());
        SimulatedRobot robot = new SimulatedRobot(state, new ControlLink(), List.of("r1", "r2"), 500, List.of(), List.of(), 1,
                java.util.Map.of());
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

    @Test
    void parametersSeedAndReportsComeFromTheWelcomeAndGoOutWithTheNextStep() {
        RobotKnowledge state = new RobotKnowledge("r1", new robosim.devices.ArRobot());
        SimulatedRobot robot = new SimulatedRobot(state, new ControlLink(), List.of("r1"), 500, List.of(), List.of(), 7,
                java.util.Map.of("speed", "300", "mode", "calm"));
        assertEquals(300, robot.parameter("speed", 500), 0);
        assertEquals(500, robot.parameter("missing", 500), 0);
        assertEquals("calm", robot.parameter("mode", "x"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> robot.parameter("mode", 1.0));
        assertEquals("parameter mode is 'calm', not a number", e.getMessage());
        assertEquals(SimulatedRobot.seed(7, "r1"), robot.seed());
        assertTrue(SimulatedRobot.seed(7, "r1") != SimulatedRobot.seed(7, "r2"), "robots of one run differ");
        assertTrue(SimulatedRobot.seed(7, "r1") != SimulatedRobot.seed(8, "r1"), "another run's seed differs");
        robot.report("found", 1);
        robot.report("t", 2.5);
        robot.report("found", 3);
        assertEquals(List.of(new robosim.protocol.Report("found", 3), new robosim.protocol.Report("t", 2.5)),
                state.takeReports(), "the newest of each name, in the order first reported");
        assertEquals(List.of(), state.takeReports());
        assertThrows(IllegalArgumentException.class, () -> robot.report("two words", 1));
        assertThrows(IllegalArgumentException.class, () -> robot.report("x", Double.POSITIVE_INFINITY));
        for (int i = 0; i < robosim.protocol.Report.MAX_PER_STEP; i++) {
            robot.report("r" + i, i);
        }
        assertThrows(IllegalArgumentException.class, () -> robot.report("one-more", 1));
        robot.report("r0", 5);
    }
}
