package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.PoseUpdate;

/** The viewer's status line: the state told truthfully, steps/s only while running. */
class StatusLineTest {
    private static Scene scene(double stepsPerSecond, ViewedRun status) {
        return new Scene(new Arena(0, 0, 1000, 1000), List.of(), List.of("rc1", "rc2"),
                List.of(robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("Scout")), new PoseUpdate(41, new double[] {1, 2},
                new double[] {1, 2}, new double[] {0, 0}), new double[][] {{}, {}}, stepsPerSecond, status);
    }

    @Test
    void eachStateReadsAsItIs() {
        assertEquals("RUNNING  2 steps/s", StatusLine.state(scene(2.04, ViewedRun.of(ViewedRun.Kind.RUNNING))));
        assertEquals("RUNNING", StatusLine.state(scene(Double.NaN, ViewedRun.of(ViewedRun.Kind.RUNNING))));
        assertEquals("PAUSED", StatusLine.state(scene(3084, ViewedRun.of(ViewedRun.Kind.PAUSED))));
        assertEquals("waiting for robots", StatusLine.state(scene(0, ViewedRun.of(ViewedRun.Kind.WAITING_FOR_ROBOTS))));
        assertEquals("STOPPED: stopped from the control port - waiting for the next run on localhost:3000",
                StatusLine.state(scene(3084, new ViewedRun(ViewedRun.Kind.STOPPED, "stopped from the control port",
                        "waiting for the next run on localhost:3000"))));
        assertEquals("connection lost: Connection reset",
                StatusLine.state(scene(5, new ViewedRun(ViewedRun.Kind.LOST, "Connection reset", ""))));
    }

    @Test
    void theWholeLineHasStepRobotsStateAndKeys() {
        assertEquals("step 42   2 robots   PAUSED      " + StatusLine.KEYS,
                StatusLine.text(scene(10, ViewedRun.of(ViewedRun.Kind.PAUSED))));
    }

    @Test
    void aReasonFromTheNetworkIsCleanedAndCut() {
        String hostile = "bad\nline\u001b[31m" + "x".repeat(500);
        String shown = StatusLine.state(scene(0, new ViewedRun(ViewedRun.Kind.STOPPED, hostile, "")));
        assertEquals("STOPPED: bad?line?[31m" + "x".repeat(StatusLine.MAX_REASON - "bad?line?[31m".length()) + "...", shown);
    }
}
