package robosim.environment.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;

/** A viewer's queue: bounded, coalescing, and never a reason for the loop to wait. */
class ViewerQueueTest {
    private static PoseUpdate update(long step) {
        return new PoseUpdate(step, new double[] {0}, new double[] {0}, new double[] {0});
    }

    @Test
    void aLiveViewerHoldsOnlyTheNewestUpdate() throws Exception {
        ViewerQueue q = new ViewerQueue(false, 0);
        for (long k = 0; k < 5000; k++) {
            assertTrue(q.hasRoom(), "a live viewer always has room");
            q.offer(update(k));
        }
        assertEquals(4999, ((PoseUpdate) q.take()).step());
        SimulationEnd end = new SimulationEnd(4999, "done");
        q.end(end);
        assertSame(end, q.take(), "nothing older was held");
    }

    @Test
    void aRecordingViewerKeepsEveryStepUpToItsBacklogThenSaysWhenItHasRoomAgain() throws Exception {
        ViewerQueue q = new ViewerQueue(true, 0);
        for (long k = 0; k < ViewerQueue.RECORDING_BACKLOG; k++) {
            assertTrue(q.hasRoom());
            q.offer(update(k));
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
        ViewerQueue q = new ViewerQueue(true, 0);
        q.offer(update(0));
        RunState paused = new RunState(1, RunState.Phase.PAUSED);
        q.state(paused);
        SimulationEnd end = new SimulationEnd(0, "done");
        assertEquals(0, ((PoseUpdate) q.take()).step());
        assertSame(paused, q.take());
        q.end(end);
        assertSame(end, q.take());
    }
}
