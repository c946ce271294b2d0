package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static robosim.runner.ControlPortTest.ok;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;
import robosim.control.ControlClient;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;
import robosim.viewer.RunFollower;
import robosim.viewer.SceneFeed;

/**
 * A viewer on a real Environment (ephemeral ports, in-JVM robots) shows pause, resume and stop as
 * they are, and follows the next run after Stop then Start and after Load: it reconnects on its own
 * and shows the new run's snapshot.
 */
class ViewerFollowTest {
    private static final Path THREE = Path.of("src/test/resources/three-robots.xml");

    /** What a viewer window would show ({@link SceneFeed}), and every event in order, to wait on. */
    private static final class Recorder implements RunFollower.Listener {
        final SceneFeed feed = new SceneFeed(System::nanoTime);
        final BlockingQueue<Object> events = new LinkedBlockingQueue<>();

        @Override
        public void snapshot(WorldSnapshot snapshot) {
            feed.snapshot(snapshot);
            events.add(snapshot);
        }

        @Override
        public void update(PoseUpdate update) {
            feed.update(update);
        }

        @Override
        public void runState(RunState state) {
            feed.runState(state);
            events.add(state);
        }

        @Override
        public void end(SimulationEnd end) {
            feed.end(end);
            events.add(end);
        }

        @Override
        public void lost(IOException cause) {
            feed.lost(cause);
            events.add(cause);
        }

        @Override
        public void between(String doing) {
            feed.between(doing);
            events.add(doing);
        }

        /** Skips events until one of the type matches; fails after a minute. */
        <T> T await(Class<T> type, Predicate<T> match) throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ControlFixture.TIMEOUT_MS);
            while (true) {
                Object e = events.poll(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
                assertNotNull(e, "no " + type.getSimpleName() + " as expected within the timeout");
                if (type.isInstance(e) && match.test(type.cast(e))) {
                    return type.cast(e);
                }
            }
        }

        RunState awaitPhase(RunState.Phase phase) throws InterruptedException {
            return await(RunState.class, s -> s.phase() == phase);
        }

        String state() {
            return robosim.viewer.StatusLine.state(feed.latest());
        }
    }

    private static long pausedAt(com.fasterxml.jackson.databind.JsonNode reply) {
        return Long.parseLong(reply.path("message").asText().substring("paused at step ".length()));
    }

    @Test
    void showsPauseAndStopAndFollowsTheNextRunAfterStartAndAfterLoad() throws Exception {
        Path other = InJvmSimulation.env("test.xml").toAbsolutePath();
        Recorder r = new Recorder();
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            int port = f.host.ports()[1];
            ViewerHello hello = new ViewerHello(false, 0);
            RunFollower follower = new RunFollower("127.0.0.1", port, hello, r, 20, 200, 0);
            follower.start(ViewerClient.connect("127.0.0.1", port, hello, ControlFixture.TIMEOUT_MS));
            try {
                r.awaitPhase(RunState.Phase.WAITING);
                assertEquals("waiting for robots", r.state());
                List<CompletableFuture<String>> robots = f.robots();
                ok(c, "step 5"); // started paused: held before step 0 (a PAUSED at step 0 may come first)
                r.await(RunState.class, s -> s.phase() == RunState.Phase.PAUSED && s.step() == 5);
                assertEquals("PAUSED", r.state());
                assertEquals(4, r.feed.latest().step(), "the poses of the last step that went out");
                ok(c, "resume");
                r.awaitPhase(RunState.Phase.RUNNING);
                ok(c, "pause");
                r.awaitPhase(RunState.Phase.PAUSED);
                assertEquals("PAUSED", r.state());

                ok(c, "stop");
                r.await(SimulationEnd.class, e -> true);
                String waiting = "waiting for the next run on 127.0.0.1:" + port;
                r.await(String.class, waiting::equals);
                assertEquals("STOPPED: stopped from the control port - " + waiting, r.state());
                for (CompletableFuture<String> robot : robots) {
                    robot.get(ControlFixture.TIMEOUT_MS, TimeUnit.MILLISECONDS);
                }

                ok(c, "start"); // the same file again: the viewer finds the new run by itself
                r.awaitPhase(RunState.Phase.WAITING);
                assertEquals("waiting for robots", r.state());
                assertEquals(-1, r.feed.latest().step(), "the new run's snapshot, before its first step");
                List<CompletableFuture<String>> again = f.robots();
                long at = pausedAt(ok(c, "step 3")); // this run was not started paused: at step 3 or later
                r.await(RunState.class, s -> s.phase() == RunState.Phase.PAUSED && s.step() == at);
                assertEquals("PAUSED", r.state());
                assertEquals(at - 1, r.feed.latest().step());

                ok(c, "load " + other); // a new file: the viewer follows it too
                r.await(SimulationEnd.class, e -> e.reason().startsWith("a new environment file was loaded"));
                r.awaitPhase(RunState.Phase.WAITING);
                assertEquals(List.of("robot1", "robot2"), r.feed.latest().names());
                assertEquals("waiting for robots", r.state());
                for (CompletableFuture<String> robot : again) {
                    robot.get(ControlFixture.TIMEOUT_MS, TimeUnit.MILLISECONDS);
                }
            } finally {
                follower.close();
            }
        }
    }
}
