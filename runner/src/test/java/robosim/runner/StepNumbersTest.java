package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.runner.ControlPortTest.ok;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.control.ControlClient;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;
import robosim.viewer.RobotFeed;
import robosim.viewer.RobotRenderer;
import robosim.viewer.Scene;
import robosim.viewer.StatusLine;

/**
 * One step number everywhere (protocol/README.md, "Step numbers"; issue 31, item 5): a paced run stopped while it
 * runs, at whatever moment the stop comes (between steps, or with a step computed and held by the pace), gives the
 * same number in the control port's reply and status, the Environment's summary line, the 2D viewer's status line
 * and the robot window's text, as their models compute them from what a viewer connection got. A replay's seek is
 * {@code ReplayTest}'s.
 */
class StepNumbersTest {
    private static final Path THREE = Path.of("src/test/resources/three-robots.xml");

    /** What a robot window would show ({@link RobotFeed}, which holds the 2D viewer's scene), and each update, to wait on. */
    private static final class Window implements ViewerClient.Listener {
        final RobotFeed feed = new RobotFeed("r1");
        final BlockingQueue<PoseUpdate> updates = new LinkedBlockingQueue<>();

        @Override
        public void snapshot(WorldSnapshot snapshot) {
            feed.snapshot(snapshot);
        }

        @Override
        public void update(PoseUpdate update) {
            feed.update(update);
            updates.add(update);
        }

        @Override
        public void robotView(RobotView view) {
            feed.robotView(view);
        }

        @Override
        public void runState(RunState state) {
            feed.runState(state);
        }

        @Override
        public void end(SimulationEnd end) {
            feed.end(end);
        }

        @Override
        public void lost(IOException cause) {
            feed.lost(cause);
        }

        void awaitStep(long atLeast) throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ControlFixture.TIMEOUT_MS);
            while (true) {
                PoseUpdate u = updates.poll(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
                assertNotNull(u, "no update of step " + atLeast + " or later within the timeout");
                if (u.step() >= atLeast) {
                    return;
                }
            }
        }
    }

    @Test
    void aStoppedRunGivesOneStepNumberInTheReplyTheSummaryTheViewerAndTheRobotWindow() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null, 20); ControlClient c = f.client(null)) {
            Window w = new Window();
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", f.host.ports()[1], new ViewerHello(false, 0, "r1"),
                    ControlFixture.TIMEOUT_MS);
            viewer.start(w);
            f.robots();
            assertEquals("paused at step 3", ok(c, "step 3").path("message").asText());
            ok(c, "resume"); // paced (40 steps/s): a stop most likely comes while a computed step waits for its time
            w.awaitStep(10);
            String stopped = ok(c, "stop").path("message").asText();
            assertTrue(stopped.matches("stopped at step [0-9]+"), stopped);
            long n = Long.parseLong(stopped.substring("stopped at step ".length()));
            viewer.awaitEnd(ControlFixture.TIMEOUT_MS, TimeUnit.MILLISECONDS);

            assertEquals(n, ok(c, "status").path("step").asLong(), "status");
            String summary = f.host.current().summary().line();
            assertTrue(summary.startsWith("summary steps=" + n + " "), summary + " after " + stopped);
            Scene scene = w.feed.latest();
            assertTrue(StatusLine.text(scene).startsWith("step " + n + " "), StatusLine.text(scene) + " after " + stopped);
            List<String> facts = RobotRenderer.facts(scene, 0, w.feed.view());
            assertTrue(facts.get(1).startsWith("step " + n + " "), facts + " after " + stopped);
            assertTrue(facts.stream().anyMatch(l -> l.startsWith("command (step " + n + ") ")), facts + " after " + stopped);
            assertTrue(w.feed.log().contains("-- the simulation ended at step " + n + ": stopped from the control port"),
                    w.feed.log() + " after " + stopped);
        }
    }
}
