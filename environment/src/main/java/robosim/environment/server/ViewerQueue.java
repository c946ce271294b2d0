package robosim.environment.server;

import java.util.ArrayDeque;
import java.util.function.LongSupplier;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.WorldSnapshot;

/**
 * What one viewer has still to be sent: bounded and coalescing, so the loop never waits on it. A live
 * viewer holds at most one update (the newest replaces it); a recording viewer ({@code everyStep}) holds
 * up to {@link #RECORDING_BACKLOG}, and when it is full the loop holds the next step back (it does not
 * wait: it goes on with its events) until this queue signals room. A live viewer that asked for at most
 * n updates a second gets the newest at most every 1/n s. A change of run state is held the same way,
 * newest only; it goes out after the updates held before it, or ahead of one that waits for the rate cap.
 * A viewer that watches a robot ({@link #watching}) gets that robot's {@link RobotView} right after each
 * update; a live viewer's newest view carries the messages of the views it replaced, and its newest update what the
 * updates it replaced drew ({@link PoseUpdate#drawnAfter}), but where it comes with a world of its own (whose drawing
 * is whole). When robots have
 * joined, a new {@link WorldSnapshot} goes right before the first update that holds them (a replaced
 * update hands its snapshot on to the one that replaces it).
 */
public final class ViewerQueue {
    public static final int RECORDING_BACKLOG = 1024;

    /**
     * An update and, for a viewer that watches a robot, its view of the step (else null), and the world
     * the update is of when robots have joined since the last update (else null).
     */
    private record Item(WorldSnapshot roster, PoseUpdate update, RobotView view) {
    }

    private final ArrayDeque<Item> pending = new ArrayDeque<>();
    private int watching = -1;
    private RobotView viewNext;
    private PoseUpdate updateNext;
    private final boolean everyStep;
    private final LongSupplier clock;
    private final long intervalNanos;
    private boolean capped;
    private long nextAllowed;
    private boolean waitingForData;
    private boolean closed;
    private boolean roomWanted;
    private boolean roomSignal;
    private SimulationEnd end;
    private RunState state;

    /** {@code clock}: what the rate cap reads the time from (ns). */
    public ViewerQueue(boolean everyStep, int maxUpdatesPerSecond, LongSupplier clock) {
        this.clock = clock;
        this.everyStep = everyStep;
        this.intervalNanos = everyStep || maxUpdatesPerSecond <= 0 ? 0 : 1_000_000_000L / maxUpdatesPerSecond;
    }

    /** Publisher's thread, at the join: the robot (world order) this viewer watches; -1 (the default) for none. */
    public synchronized void watch(int robot) {
        watching = robot;
    }

    /** The robot this viewer watches, or -1. */
    public synchronized int watching() {
        return watching;
    }

    /** Loop thread: true if one more update fits now; if not, the queue will signal room once it has some. */
    public synchronized boolean hasRoom() {
        if (closed || !everyStep || pending.size() < RECORDING_BACKLOG) {
            return true;
        }
        roomWanted = true;
        return false;
    }

    /**
     * Loop thread: the step's poses, the world they are of when robots have joined since the last step (else
     * null), and the watched robot's view of the step (null if it watches none or the robot is not in the
     * step). Never blocks; the loop has checked {@link #hasRoom} first. A live viewer's update replaces the
     * one held (and takes on its world); a view held with it is merged into the new view, or, when there is
     * none (the robot has left), kept with its update ahead of the new one: no message is lost.
     */
    public synchronized void offer(WorldSnapshot roster, PoseUpdate update, RobotView view) {
        if (closed) {
            return;
        }
        if (!everyStep) {
            boolean ownWorld = roster != null; // (its world's drawing is whole: what the dropped drew is in it)
            Item replaced = pending.pollLast();
            PoseUpdate between = null; // (a view-less update dropped after the one replaced, if any)
            if (replaced != null && replaced.view() == null && replaced.roster() == null) {
                Item kept = pending.pollLast(); // (a view kept ahead of a view-less update, if any: see below)
                if (kept != null) {
                    between = replaced.update();
                    replaced = kept;
                }
            }
            if (replaced != null && roster == null) {
                roster = replaced.roster(); // (the newer update is of that world too)
            }
            if (replaced != null && replaced.view() != null) {
                if (view != null) {
                    view = view.after(replaced.view());
                } else {
                    pending.addLast(replaced); // (so at most two are held: a view kept, and the newest update)
                    replaced = null;
                }
            }
            if (between != null && !ownWorld) { // (dropped: what their steps drew, the newest draws after it, in order)
                update = update.drawnAfter(between);
            }
            if (replaced != null && !ownWorld) {
                update = update.drawnAfter(replaced.update());
            }
        }
        pending.addLast(new Item(roster, update, view));
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
        viewNext = null;
        updateNext = null;
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
     * viewer) and the watched robot's view right after it, a run state, or the end ({@link SimulationEnd},
     * the last).
     */
    public synchronized Object take() throws InterruptedException {
        if (updateNext != null) { // (the update goes right after its world's snapshot)
            PoseUpdate u = updateNext;
            updateNext = null;
            return u;
        }
        if (viewNext != null) { // (the view goes right after its update, whatever the cap)
            RobotView v = viewNext;
            viewNext = null;
            return v;
        }
        while (true) {
            if (pending.isEmpty() && end != null) {
                return end;
            }
            long early = capped ? nextAllowed - clock.getAsLong() : 0;
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
                    nextAllowed = clock.getAsLong() + intervalNanos;
                }
                Item next = pending.pollFirst();
                viewNext = next.view();
                if (roomWanted && pending.size() < RECORDING_BACKLOG) {
                    roomWanted = false;
                    roomSignal = true;
                }
                if (next.roster() != null) {
                    updateNext = next.update();
                    return next.roster();
                }
                return next.update();
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
