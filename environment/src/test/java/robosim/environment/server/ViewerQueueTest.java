package robosim.environment.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.CommEvent;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;

/** A viewer's queue: bounded, coalescing, and never a reason for the loop to wait. */
class ViewerQueueTest {
    private static final long SECOND = 1_000_000_000L;

    private static PoseUpdate update(long step) {
        return new PoseUpdate(step, new double[] {0}, new double[] {0}, new double[] {0});
    }

    @Test
    void aLiveViewerHoldsOnlyTheNewestUpdate() throws Exception {
        ViewerQueue q = new ViewerQueue(false, 0, System::nanoTime);
        for (long k = 0; k < 5000; k++) {
            assertTrue(q.hasRoom(), "a live viewer always has room");
            q.offer(null, update(k), null);
        }
        assertEquals(4999, ((PoseUpdate) q.take()).step());
        SimulationEnd end = new SimulationEnd(4999, "done");
        q.end(end);
        assertSame(end, q.take(), "nothing older was held");
    }

    @Test
    void theWorldAfterAJoinGoesRightBeforeItsFirstUpdateAndALiveViewerKeepsItWhenTheUpdateIsReplaced()
            throws Exception {
        WorldSnapshot grown = new WorldSnapshot(500, new Arena(0, 0, 1000, 1000), List.of(), List.of("a", "b"),
                List.of(robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("Scout")),
                new PoseUpdate(1, new double[] {0, 1}, new double[] {0, 1}, new double[] {0, 0}));
        ViewerQueue recording = new ViewerQueue(true, 0, System::nanoTime);
        recording.offer(null, update(0), null);
        recording.offer(grown, update(1), null);
        recording.offer(null, update(2), null);
        assertEquals(0, ((PoseUpdate) recording.take()).step());
        assertSame(grown, recording.take(), "the world, then the first update of it");
        assertEquals(1, ((PoseUpdate) recording.take()).step());
        assertEquals(2, ((PoseUpdate) recording.take()).step());
        ViewerQueue live = new ViewerQueue(false, 0, System::nanoTime);
        live.offer(grown, update(1), null);
        live.offer(null, update(2), null);
        live.offer(null, update(3), null);
        assertSame(grown, live.take(), "the replaced update handed its world on");
        assertEquals(3, ((PoseUpdate) live.take()).step());
        live.offer(null, update(4), null);
        assertEquals(4, ((PoseUpdate) live.take()).step(), "the world once");
    }

    @Test
    void aLiveViewersNewestUpdateDrawsWhatTheUpdatesItReplacedDrew() throws Exception {
        robosim.protocol.Traces.Log source = new robosim.protocol.Traces.Log();
        robosim.protocol.Traces.Log viewer = new robosim.protocol.Traces.Log();
        ViewerQueue q = new ViewerQueue(false, 0, System::nanoTime);
        q.watch(0);
        for (long k = 0; k < 6; k++) { // (views on even steps: a view kept ahead of a view-less update, then both go)
            source.add("fb", k, 0, 0xFF0000);
            PoseUpdate drew = update(k).withExperiment(List.of(), List.of(), List.of(), source.since(),
                    source.whole(), new int[0]);
            q.offer(null, drew, k % 2 == 0 ? view(k, "m" + k) : null);
        }
        List<Long> steps = new java.util.ArrayList<>();
        for (int k = 0; k < 3 && (steps.isEmpty() || steps.get(steps.size() - 1) < 5); k++) { // (3 held at most)
            if (q.take() instanceof PoseUpdate sent) { // (and the view kept, after its update)
                steps.add(sent.step());
                viewer.apply(sent.traces());
            }
        }
        assertEquals(List.of(4L, 5L), steps, "the view's update kept, then the newest");
        assertEquals(6, viewer.points(), "every point drawn");
        assertEquals(5, viewer.whole().xMm(5));
    }

    @Test
    void aRecordingViewerKeepsEveryStepUpToItsBacklogThenSaysWhenItHasRoomAgain() throws Exception {
        ViewerQueue q = new ViewerQueue(true, 0, System::nanoTime);
        for (long k = 0; k < ViewerQueue.RECORDING_BACKLOG; k++) {
            assertTrue(q.hasRoom());
            q.offer(null, update(k), null);
        }
        assertFalse(q.hasRoom(), "full: the loop holds the next step");
        assertFalse(q.claimRoomSignal());
        assertEquals(0, ((PoseUpdate) q.take()).step(), "every step, oldest first");
        assertTrue(q.claimRoomSignal(), "the worker tells the loop once");
        assertFalse(q.claimRoomSignal());
        assertTrue(q.hasRoom());
    }

    @Test
    void theEndComesAfterEveryHeldUpdateAndARunStateAfterTheUpdatesBeforeIt() throws Exception {
        ViewerQueue q = new ViewerQueue(true, 0, System::nanoTime);
        q.offer(null, update(0), null);
        RunState paused = new RunState(1, RunState.Phase.PAUSED);
        q.state(paused);
        SimulationEnd end = new SimulationEnd(0, "done");
        assertEquals(0, ((PoseUpdate) q.take()).step());
        assertSame(paused, q.take());
        q.end(end);
        assertSame(end, q.take());
    }

    private static RobotView view(long step, String text) {
        return RobotView.of(step, 0, "a", new StepRequest(step, 10, 0, false, List.of(new CommEvent("a", "b", text))),
                new StepResponse(step, 10, 0, "", 0, 0, 0, new double[0], List.of(), List.of()));
    }

    @Test
    void aWatchedRobotsViewGoesRightAfterItsUpdateAndALiveViewerMissesNoMessage() throws Exception {
        long[] now = {1};
        // (one update a second, on a clock of the test's: the view must not wait for the cap; an update waits for it
        // until the test moves the clock on, so no take here waits)
        ViewerQueue q = new ViewerQueue(false, 1, () -> now[0]);
        q.watch(0);
        assertEquals(0, q.watching());
        q.offer(null, update(0), view(0, "m0"));
        assertEquals(0, ((PoseUpdate) q.take()).step());
        assertEquals(0, ((RobotView) q.take()).step(), "the view at once after its update");
        for (long k = 1; k <= 3; k++) {
            q.offer(null, update(k), view(k, "m" + k));
        }
        now[0] += SECOND;
        assertEquals(3, ((PoseUpdate) q.take()).step(), "the newest update");
        RunState running = new RunState(4, RunState.Phase.RUNNING);
        q.state(running); // (a state goes ahead of an update that waits for the cap; not ahead of its view)
        RobotView v = (RobotView) q.take();
        assertEquals(3, v.step());
        assertEquals(1, v.sinceStep(), "with the messages of the views it replaced");
        assertEquals(List.of("m1", "m2", "m3"), v.sent().stream().map(CommEvent::payload).toList());
        assertSame(running, q.take());
        q.offer(null, update(4), view(4, "m4"));
        q.offer(null, update(5), null); // (the robot has left: its last view is not dropped for the newest update)
        now[0] += SECOND;
        assertEquals(4, ((PoseUpdate) q.take()).step());
        assertEquals(List.of("m4"), ((RobotView) q.take()).sent().stream().map(CommEvent::payload).toList());
        now[0] += SECOND;
        assertEquals(5, ((PoseUpdate) q.take()).step());
        for (long k = 6; k < 12; k += 2) { // (a replay sought back and forth across the robot's departure)
            q.offer(null, update(k), view(k, "m" + k));
            q.offer(null, update(k + 1), null);
        }
        now[0] += SECOND;
        assertEquals(10, ((PoseUpdate) q.take()).step(), "at most two held: the last view kept, with its update");
        assertEquals(List.of("m6", "m8", "m10"), ((RobotView) q.take()).sent().stream().map(CommEvent::payload).toList());
        now[0] += SECOND;
        assertEquals(11, ((PoseUpdate) q.take()).step(), "and the newest update");
        SimulationEnd end = new SimulationEnd(5, "done");
        q.end(end);
        assertSame(end, q.take());
    }
}
