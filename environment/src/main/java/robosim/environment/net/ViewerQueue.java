package robosim.environment.net;

import java.util.ArrayDeque;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;

/**
 * What one viewer has still to be sent: bounded and coalescing, so the loop never waits on it. A live
 * viewer holds at most one update (the newest replaces it); a recording viewer ({@code everyStep}) holds
 * up to {@link #RECORDING_BACKLOG}, and when it is full the loop holds the next step back (it does not
 * wait: it goes on with its events) until this queue signals room. A live viewer that asked for at most
 * n updates a second gets the newest at most every 1/n s. A change of run state is held the same way,
 * newest only; it goes out after the updates held before it, or ahead of one that waits for the rate cap.
 */
public final class ViewerQueue {
    public static final int RECORDING_BACKLOG = 1024;

    private final ArrayDeque<PoseUpdate> pending = new ArrayDeque<>();
    private final boolean everyStep;
    private final long intervalNanos;
    private boolean capped;
    private long nextAllowed;
    private boolean waitingForData;
    private boolean closed;
    private boolean roomWanted;
    private boolean roomSignal;
    private SimulationEnd end;
    private RunState state;

    public ViewerQueue(boolean everyStep, int maxUpdatesPerSecond) {
        this.everyStep = everyStep;
        this.intervalNanos = everyStep || maxUpdatesPerSecond <= 0 ? 0 : 1_000_000_000L / maxUpdatesPerSecond;
    }

    /** Loop thread: true if one more update fits now; if not, the queue will signal room once it has some. */
    public synchronized boolean hasRoom() {
        if (closed || !everyStep || pending.size() < RECORDING_BACKLOG) {
            return true;
        }
        roomWanted = true;
        return false;
    }

    /** Loop thread: the step's poses. Never blocks; the loop has checked {@link #hasRoom} first. */
    public synchronized void offer(PoseUpdate update) {
        if (closed) {
            return;
        }
        if (!everyStep) {
            pending.clear();
        }
        pending.addLast(update);
        if (waitingForData) {
            notifyAll();
        }
    }

    /** Loop thread: the run now runs or is held. Never blocks. */
    public synchronized void state(RunState newState) {
        if (!closed) {
            state = newState;
            notifyAll(); // rare: also cuts short a wait for the update-rate cap
        }
    }

    public synchronized void end(SimulationEnd message) {
        end = message;
        notifyAll();
    }

    /** The viewer is gone: nothing more is kept. */
    public synchronized void close() {
        closed = true;
        pending.clear();
        notifyAll();
    }

    /** True once, after a take that made room the loop was waiting for. */
    public synchronized boolean claimRoomSignal() {
        boolean s = roomSignal;
        roomSignal = false;
        return s;
    }

    /**
     * Worker thread: the next thing to send - an update (at most one per interval for a capped live
     * viewer), a run state, or the end ({@link SimulationEnd}, the last).
     */
    public synchronized Object take() throws InterruptedException {
        while (true) {
            if (pending.isEmpty() && end != null) {
                return end;
            }
            long early = capped ? nextAllowed - System.nanoTime() : 0;
            if ((pending.isEmpty() || early > 0) && state != null && end == null) {
                RunState s = state;
                state = null;
                return s;
            }
            if (early > 0) {
                wait(early / 1_000_000, (int) (early % 1_000_000));
                continue;
            }
            if (!pending.isEmpty()) {
                if (intervalNanos > 0) {
                    capped = true;
                    nextAllowed = System.nanoTime() + intervalNanos;
                }
                PoseUpdate next = pending.pollFirst();
                if (roomWanted && pending.size() < RECORDING_BACKLOG) {
                    roomWanted = false;
                    roomSignal = true;
                }
                return next;
            }
            waitingForData = true;
            try {
                wait();
            } finally {
                waitingForData = false;
            }
        }
    }
}
