package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotModels;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.WorldSnapshot;

/** Scenes from the network: trails bounded, scenes immutable, the end shown in the status. */
class SceneFeedTest {
    private static PoseUpdate at(long step, double x) {
        return new PoseUpdate(step, new double[] {x}, new double[] {1000}, new double[] {0});
    }

    @Test
    void trailsAreBoundedAndScenesAreNotChangedAfterPublication() {
        SceneFeed feed = new SceneFeed(0);
        feed.snapshot(new WorldSnapshot(500, new Arena(0, 0, 100_000, 2000), List.of(), List.of("a"),
                List.of(RobotModels.SCOUT), at(-1, 1000)));
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
        SceneFeed feed = new SceneFeed(1_000_000_000_000L); // updates published rarely; states at once
        feed.snapshot(new WorldSnapshot(500, new Arena(0, 0, 10_000, 2000), List.of(), List.of("a"),
                List.of(RobotModels.SCOUT), at(-1, 1000)));
        feed.runState(new RunState(0, RunState.Phase.RUNNING));
        assertEquals("RUNNING", StatusLine.state(feed.latest()), "no rate before one is measured");
        for (int k = 0; k < 5; k++) {
            feed.update(at(k, 1000 + k));
        }
        feed.runState(new RunState(5, RunState.Phase.PAUSED));
        assertEquals("PAUSED", StatusLine.state(feed.latest()));
        assertEquals(4, feed.latest().step(), "the newest poses, though not yet published as a frame");
        feed.end(new SimulationEnd(4, "stopped from the control port"));
        feed.between("waiting for the next run on localhost:3000");
        assertEquals("STOPPED: stopped from the control port - waiting for the next run on localhost:3000",
                StatusLine.state(feed.latest()));
        feed.snapshot(new WorldSnapshot(500, new Arena(0, 0, 10_000, 2000), List.of(), List.of("b", "c"),
                List.of(RobotModels.SCOUT, RobotModels.AR_ROBOT), new PoseUpdate(-1, new double[] {1, 2},
                new double[] {1, 2}, new double[] {0, 0})));
        Scene next = feed.latest();
        assertEquals("waiting for robots", StatusLine.state(next));
        assertEquals(List.of("b", "c"), next.names());
        assertEquals(-1, next.step());
        assertEquals(2, next.trails()[1].length, "the new run's trails start afresh");
    }
}
