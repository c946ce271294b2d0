package robosim.environment.net;

import java.io.IOException;
import java.net.Socket;
import java.util.ArrayDeque;
import robosim.protocol.PoseUpdate;
import robosim.protocol.Protocol;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * Serves one viewer: the snapshot, then pose updates, from its own thread. The step thread only
 * {@link #offer}s the newest update. A live viewer holds at most one pending update (newer ones
 * replace it), so a slow or frozen viewer never slows the robots and its memory stays bounded. A
 * recording viewer holds up to {@link #RECORDING_BACKLOG} and, past that, makes the step wait. A
 * live viewer that asked for at most n updates a second gets the newest pose at most every 1/n s,
 * and the step thread wakes its worker only when the worker is waiting for data. A change of run
 * state (running, paused) is held the same way, newest only; it goes out after the updates held
 * before it, or ahead of one that is waiting for the update-rate cap (a state never waits for it).
 */
final class ViewerClientWorker extends ClientWorker {
    static final int RECORDING_BACKLOG = 1024;
    /**
     * Kernel send buffer for a viewer: enough for dozens of updates, so a live viewer never waits on
     * it, while a viewer that stops reading blocks its worker after this much instead of after the
     * megabytes loopback would otherwise allow (until then its worker would wake every step).
     */
    static final int SEND_BUFFER_BYTES = 64 * 1024;

    private final ArrayDeque<PoseUpdate> pending = new ArrayDeque<>();
    private boolean everyStep;
    private long intervalNanos;
    private boolean capped;
    private long nextAllowed;
    private final java.util.concurrent.CountDownLatch done = new java.util.concurrent.CountDownLatch(1);
    private boolean waitingForData;
    private boolean closed;
    private SimulationEnd end;
    /** The newest run state not yet sent (a newer one replaces it), or null. */
    private RunState state;
    private int maxPending;

    ViewerClientWorker(ClientWorkerCoordinator coordinator, Socket socket, int serial) {
        super(coordinator, socket, "viewer-worker[" + serial + "]");
    }

    @Override
    protected void configure(Socket s) throws IOException {
        s.setSendBufferSize(SEND_BUFFER_BYTES);
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        ViewerHello hello = connection.read(ViewerHello.class);
        if (hello.protocolVersion() != Protocol.VERSION) {
            String refusal = "protocol version " + hello.protocolVersion() + " is not supported (the Environment "
                    + "speaks " + Protocol.VERSION + ")";
            coordinator.log().warn("{} refused: {}", name(), refusal);
            connection.write(new SimulationEnd(-1, refusal));
            connection.flush();
            return;
        }
        synchronized (this) {
            everyStep = hello.everyStep();
            intervalNanos = everyStep || hello.maxUpdatesPerSecond() == 0 ? 0
                    : 1_000_000_000L / hello.maxUpdatesPerSecond();
        }
        connection.setReadTimeoutMs(0);
        WorldSnapshot snapshot = coordinator.addViewer(this);
        connection.write(snapshot);
        connection.flush();
        while (true) {
            Object next = take();
            if (next instanceof PoseUpdate u) {
                connection.write(u);
                connection.flush();
            } else if (next instanceof RunState s) {
                connection.write(s);
                connection.flush();
            } else {
                connection.write((SimulationEnd) next);
                connection.flush();
                return;
            }
        }
    }

    /** Called by the step thread with each step's poses. Never blocks for a live viewer. */
    synchronized void offer(PoseUpdate update) throws InterruptedException {
        if (closed) {
            return;
        }
        if (!everyStep) {
            pending.clear();
        } else {
            while (pending.size() >= RECORDING_BACKLOG && !closed) {
                wait();
            }
        }
        pending.addLast(update);
        maxPending = Math.max(maxPending, pending.size());
        if (waitingForData) {
            notifyAll();
        }
    }

    /** Called under the coordinator's lock when the run starts, pauses or resumes. Never blocks. */
    synchronized void state(RunState newState) {
        if (closed) {
            return;
        }
        state = newState;
        notifyAll(); // rare: also cuts short a wait for the update-rate cap
    }

    synchronized void end(SimulationEnd message) {
        end = message;
        notifyAll();
    }

    /** The next thing to send: an update (at most one per interval for a capped live viewer), or the end. */
    private synchronized Object take() throws InterruptedException {
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
                notifyAll();
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

    synchronized boolean recording() {
        return everyStep;
    }

    /** The most updates this viewer ever had waiting. */
    synchronized int maxPending() {
        return maxPending;
    }

    /** Waits until this worker has sent everything it holds (or its connection is gone). */
    boolean awaitDone(long nanos) throws InterruptedException {
        return done.await(nanos, java.util.concurrent.TimeUnit.NANOSECONDS);
    }

    @Override
    protected void exited(String why) {
        synchronized (this) {
            closed = true;
            pending.clear();
            notifyAll();
        }
        coordinator.removeViewer(this, why);
        done.countDown();
    }
}
