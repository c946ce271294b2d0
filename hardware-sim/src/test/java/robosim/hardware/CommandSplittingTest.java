package robosim.hardware;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.api.RobotControl;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * The splitting rule: step 500 ms, 500 mm/s: move(750) is exactly three steps of 250 mm; and how
 * sleep rounds to whole steps.
 */
class CommandSplittingTest {
    private static StepResponse moved(double mm, double deg) {
        return new StepResponse(0, mm, deg, "", 0, 0, 0, new double[0], List.of(), List.of());
    }

    @Test
    void move750TakesThreeStepsOf250() {
        Command c = Command.move(750, 500);
        List<Double> pieces = new ArrayList<>();
        boolean done = false;
        while (!done) {
            c.plan(0.5);
            pieces.add(c.plannedMoveMm);
            done = c.apply(moved(c.plannedMoveMm, 0), false);
        }
        assertEquals(List.of(250.0, 250.0, 250.0), pieces);
        assertEquals(750, c.result);
    }

    @Test
    void aShortLastPieceAndBackwardsMoves() {
        Command c = Command.move(-600, 500);
        List<Double> pieces = new ArrayList<>();
        boolean done = false;
        while (!done) {
            c.plan(0.5);
            pieces.add(c.plannedMoveMm);
            done = c.apply(moved(c.plannedMoveMm, 0), false);
        }
        assertEquals(List.of(-250.0, -250.0, -100.0), pieces);
    }

    @Test
    void aBlockedMoveEndsAtOnceWithTheDistanceCovered() {
        Command c = Command.move(1000, 500);
        c.plan(0.5);
        assertFalse(c.apply(moved(250, 0), false));
        c.plan(0.5);
        assertTrue(c.apply(moved(40, 0), false), "touching something ends the move");
        assertEquals(290, c.result);
    }

    @Test
    void turn180At90DegPerSecondTakesFourSteps() {
        Command c = Command.turn(180, 90);
        int steps = 0;
        boolean done = false;
        while (!done) {
            c.plan(0.5);
            assertEquals(45, c.plannedTurnDeg);
            done = c.apply(moved(0, c.plannedTurnDeg), false);
            steps++;
        }
        assertEquals(4, steps);
    }

    /**
     * Through a real Hardware Simulator and a scripted Environment on a loopback socket: the control
     * code's move(750), turn(90), send and sleep show up as exactly these requests, step by step.
     */
    @Test
    void theHardwareSimulatorSendsOnePiecePerStepWithNoIdleStepsBetweenCalls() throws Exception {
        RobotControl control = robot -> {
            robot.move(750);
            robot.send("robot2", "hello");
            robot.turn(90);
            robot.sleep(1000);
        };
        ScriptedEnvironment.Run run = ScriptedEnvironment.run(control, 500, 9);
        assertEquals(ScriptedEnvironment.END_REASON, run.endReason());
        assertEquals("ArRobot", run.hello().properties().type());
        List<StepRequest> seen = run.requests();
        double[] moves = seen.stream().mapToDouble(StepRequest::moveMm).toArray();
        double[] turns = seen.stream().mapToDouble(StepRequest::turnDeg).toArray();
        assertEquals(List.of(250.0, 250.0, 250.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), box(moves));
        assertEquals(List.of(0.0, 0.0, 0.0, 45.0, 45.0, 0.0, 0.0, 0.0, 0.0), box(turns));
        assertEquals("hello", seen.get(3).messages().get(0).payload(), "the message goes out with the next step");
        assertEquals("robot2", seen.get(3).messages().get(0).to());
        assertTrue(seen.get(0).wantsSonar());
    }

    /**
     * sleep(ms) rounds up to whole steps and takes at least one: with 250 ms steps, sleep(0) and
     * sleep(250) take one step, sleep(251) two, sleep(600) three. Each sleep is preceded by a message
     * naming it, which goes out with that sleep's first step, so the steps between two messages are
     * the steps the sleep between them took.
     */
    @Test
    void sleepRoundsUpToWholeStepsAndTakesAtLeastOne() throws Exception {
        long[] sleeps = {0, 250, 251, 600, 1};
        RobotControl control = robot -> {
            for (long ms : sleeps) {
                robot.send("robot2", "sleep " + ms);
                robot.sleep(ms);
            }
        };
        List<StepRequest> seen = ScriptedEnvironment.run(control, 250, 10).requests();
        List<Integer> firstSteps = new ArrayList<>();
        for (int k = 0; k < seen.size(); k++) {
            if (!seen.get(k).messages().isEmpty()) {
                assertEquals("sleep " + sleeps[firstSteps.size()], seen.get(k).messages().get(0).payload());
                firstSteps.add(k);
            }
        }
        assertEquals(List.of(0, 1, 2, 4, 7), firstSteps, "steps taken: 1, 1, 2, 3, then sleep(1) from step 7");
        assertTrue(seen.stream().allMatch(q -> q.moveMm() == 0 && q.turnDeg() == 0), "sleeping stands still");
    }

    /** The longest sleep (and wait) stays asleep: rounding up does not overflow into a one-step sleep. */
    @Test
    void sleepOfLongMaxValueDoesNotEnd() throws Exception {
        RobotControl control = robot -> {
            robot.sleep(Long.MAX_VALUE);
            robot.send("robot2", "woke up");
        };
        List<StepRequest> seen = ScriptedEnvironment.run(control, 250, 6).requests();
        assertEquals(6, seen.size());
        assertTrue(seen.stream().allMatch(q -> q.messages().isEmpty()), "still asleep after 6 steps");
    }

    private static List<Double> box(double[] a) {
        List<Double> l = new ArrayList<>();
        for (double v : a) {
            l.add(v);
        }
        return l;
    }
}
