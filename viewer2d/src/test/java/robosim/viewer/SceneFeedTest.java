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
        assertEquals("waiting for robots", first.status());
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
        assertEquals("simulation over: completed 2000 steps", feed.latest().status());
        assertSame(s.poses(), feed.latest().poses());
        assertTrue(ViewerWindow.statusLine(feed.latest()).startsWith("step 2000 "));
    }
}
