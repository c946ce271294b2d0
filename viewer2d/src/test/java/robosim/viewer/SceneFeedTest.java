package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.WorldSnapshot;

/**
 * Scenes from the network: trails bounded, scenes immutable, the end shown in the status, every update shown at
 * once, a replay's seek starting the picture afresh at the sought step.
 */
class SceneFeedTest {
    private static final Arena ARENA = new Arena(0, 0, 100_000, 2000);

    private static PoseUpdate at(long step, double x) {
        return new PoseUpdate(step, new double[] {x}, new double[] {1000}, new double[] {0});
    }

    /** The world of robot "a" standing where {@code poses} say, as a replay's seek or the start sends it. */
    private static WorldSnapshot world(PoseUpdate poses) {
        return new WorldSnapshot(500, ARENA, List.of(), List.of("a"), List.of(robosim.devices.RobotTypes.properties("Scout")), poses);
    }

    @Test
    void whatTheLoopFunctionsDrewIsPiecedTogetherAndAnEarlierSceneKeepsItsOwn() {
        robosim.protocol.Traces.Log source = new robosim.protocol.Traces.Log();
        source.add("a", 10, 20, 0x00FF00);
        PoseUpdate start = at(-1, 1000).withExperiment(List.of(), List.of(), List.of(), source.since(),
                source.whole(), new int[0]);
        SceneFeed feed = new SceneFeed(System::nanoTime);
        feed.snapshot(world(start.posesOnly()));
        Scene first = feed.latest();
        for (int k = 0; k < 50; k++) {
            source.add(k % 2 == 0 ? "a" : "b", k, k, 0x00FF00);
            feed.update(at(k, 1000).withExperiment(List.of(), List.of(), List.of(), source.since(), source.whole(), new int[0]));
        }
        robosim.protocol.Traces drawn = feed.latest().poses().traces();
        assertTrue(drawn.fresh(), "a scene holds the whole drawing");
        assertEquals(51, drawn.points());
        assertEquals(2, drawn.traces());
        assertEquals(49, drawn.xMm(50));
        assertEquals(1, first.poses().traces().points(), "the first scene's drawing as it was");
        source.erase();
        feed.update(at(50, 1000).withExperiment(List.of(), List.of(), List.of(), source.since(), source.whole(), new int[0]));
        assertEquals(0, feed.latest().poses().traces().points(), "erased");
    }

    @Test
    void trailsAreBoundedAndScenesAreNotChangedAfterPublication() {
        SceneFeed feed = new SceneFeed(System::nanoTime);
        feed.snapshot(world(at(-1, 1000)));
        Scene first = feed.latest();
        assertEquals(ViewedRun.of(ViewedRun.Kind.WAITING_FOR_ROBOTS), first.status());
        for (int k = 0; k < 2000; k++) {
            feed.update(at(k, 1000 + 50.0 * (k + 1)));
        }
        Scene s = feed.latest();
        assertNotSame(first, s);
        assertEquals(1999, s.step());
        assertEquals(2 * SceneFeed.TRAIL_POINTS, s.trails()[0].length, "trail holds at most TRAIL_POINTS points");
        assertEquals(1000 + 50.0 * 2000, s.trails()[0][s.trails()[0].length - 2], "newest point last");
        assertEquals(1, first.trails()[0].length / 2, "an earlier scene keeps its own trail");
        feed.end(new SimulationEnd(1999, "completed 2000 steps"));
        assertEquals(new ViewedRun(ViewedRun.Kind.STOPPED, "completed 2000 steps", ""), feed.latest().status());
        assertSame(s.poses(), feed.latest().poses());
        assertTrue(StatusLine.text(feed.latest()).startsWith("step 2000 "));
    }

    @Test
    void pauseResumeStopAndTheNextRunShowInTheStatusAtOnce() {
        SceneFeed feed = new SceneFeed(System::nanoTime);
        feed.snapshot(world(at(-1, 1000)));
        feed.runState(new RunState(0, RunState.Phase.RUNNING));
        assertEquals("RUNNING", StatusLine.state(feed.latest()), "no rate before one is measured");
        for (int k = 0; k < 5; k++) {
            feed.update(at(k, 1000 + k));
        }
        feed.runState(new RunState(5, RunState.Phase.PAUSED));
        assertEquals("PAUSED", StatusLine.state(feed.latest()));
        assertEquals(4, feed.latest().step(), "the newest poses");
        feed.end(new SimulationEnd(4, "stopped from the control port"));
        feed.between("waiting for the next run on localhost:3000");
        assertEquals("STOPPED: stopped from the control port - waiting for the next run on localhost:3000",
                StatusLine.state(feed.latest()));
        feed.snapshot(new WorldSnapshot(500, ARENA, List.of(), List.of("b", "c"),
                List.of(robosim.devices.RobotTypes.properties("Scout"), robosim.devices.RobotTypes.properties("ArRobot")), new PoseUpdate(-1, new double[] {1, 2},
                new double[] {1, 2}, new double[] {0, 0})));
        Scene next = feed.latest();
        assertEquals("waiting for robots", StatusLine.state(next));
        assertEquals(List.of("b", "c"), next.names());
        assertEquals(-1, next.step());
        assertEquals(2, next.trails()[1].length, "the new run's trails start afresh");
    }

    @Test
    void everyUpdateIsShownAtOnceWithItsOwnStep() {
        long[] now = {0};
        SceneFeed feed = new SceneFeed(() -> now[0]);
        feed.snapshot(world(at(-1, 1000)));
        feed.runState(new RunState(0, RunState.Phase.PAUSED));
        for (int k = 0; k < 3; k++) { // (steps a paused run is stepped through, a millisecond apart)
            now[0] += 1_000_000;
            feed.update(at(k, 2000 + 100 * k));
            assertEquals(k, feed.latest().step(), "the picture is the newest update's");
            assertEquals(2000 + 100 * k, feed.latest().poses().xMm(0), "its poses are that update's");
        }
    }

    @Test
    void aSeekStartsThePictureAfreshAtTheSoughtStepAndKeepsTheRunsState() {
        long[] now = {0};
        SceneFeed feed = new SceneFeed(() -> now[0]);
        feed.snapshot(world(at(-1, 1000)));
        feed.runState(new RunState(0, RunState.Phase.RUNNING));
        for (int k = 0; k <= 1606; k++) { // 10 steps a second, 50 mm a step
            now[0] += 100_000_000;
            feed.update(at(k, 1000 + 50.0 * k));
        }
        assertEquals(10, feed.latest().stepsPerSecond(), 1e-9);
        feed.runState(new RunState(1607, RunState.Phase.PAUSED));

        now[0] += 1_000_000; // a seek back while paused, as the replay sends it: the world at step 100, its update
        PoseUpdate sought = at(100, 1000 + 50.0 * 100);
        feed.snapshot(world(sought));
        feed.update(sought);
        Scene s = feed.latest();
        assertEquals(100, s.step());
        assertEquals(sought.xMm(0), s.poses().xMm(0), "the robot where the sought step has it");
        assertEquals("PAUSED", StatusLine.state(s), "still paused: the run's state is kept");
        assertTrue(StatusLine.text(s).startsWith("step 101 "), StatusLine.text(s));
        assertArrayEquals(new double[] {sought.xMm(0), 1000}, s.trails()[0], "the trail starts afresh there");
        assertTrue(Double.isNaN(s.stepsPerSecond()), "the rate is measured afresh");

        feed.runState(new RunState(101, RunState.Phase.RUNNING)); // resumed at x0.1: a step a second
        for (int k = 101; k <= 103; k++) {
            now[0] += 1_000_000_000;
            feed.update(at(k, 1000 + 50.0 * k));
        }
        assertEquals(1, feed.latest().stepsPerSecond(), 1e-9);

        now[0] += 300_000_000; // a seek forward while running
        sought = at(1500, 90_000);
        feed.snapshot(world(sought));
        feed.update(sought);
        assertEquals("RUNNING", StatusLine.state(feed.latest()), "running on, the rate not yet measured afresh");
        assertArrayEquals(new double[] {90_000, 1000}, feed.latest().trails()[0], "no line across the jump");
        for (int k = 1501; k <= 1502; k++) {
            now[0] += 1_000_000_000;
            feed.update(at(k, 90_000 + 50.0 * (k - 1500)));
        }
        assertEquals(1, feed.latest().stepsPerSecond(), 1e-9, "a step a second, as the replay runs");
        assertEquals(3, feed.latest().trails()[0].length / 2, "the sought step's point and the two after it");
    }
}
