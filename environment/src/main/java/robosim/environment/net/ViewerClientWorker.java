package robosim.environment.net;

import java.io.IOException;
import java.net.Socket;
import java.util.ArrayDeque;
import robosim.protocol.PoseUpdate;
import robosim.protocol.Protocol;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * Serves one viewer: the snapshot, then pose updates, from its own thread. The step thread only
 * {@link #offer}s the newest update. A live viewer holds at most one pending update (newer ones
 * replace it), so a slow or frozen viewer never slows the robots and its memory stays bounded. A
 * recording viewer holds up to {@link #RECORDING_BACKLOG} and, past that, makes the step wait.
 */
final class ViewerClientWorker extends ClientWorker {
    static final int RECORDING_BACKLOG = 1024;

    private final ArrayDeque<PoseUpdate> pending = new ArrayDeque<>();
    private boolean everyStep;
    private boolean closed;
    private SimulationEnd end;
    private int maxPending;

    ViewerClientWorker(ClientWorkerCoordinator coordinator, Socket socket, int serial) {
        super(coordinator, socket, "viewer-worker[" + serial + "]");
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
        notifyAll();
    }

    synchronized void end(SimulationEnd message) {
        end = message;
        notifyAll();
    }

    private synchronized Object take() throws InterruptedException {
        while (pending.isEmpty() && end == null) {
            wait();
        }
        Object next = pending.isEmpty() ? end : pending.pollFirst();
        notifyAll();
        return next;
    }

    synchronized boolean recording() {
        return everyStep;
    }

    /** Closes the connection; a worker blocked writing to a frozen viewer then ends. */
    void drop() {
        if (connection != null) {
            connection.close();
        }
    }

    /** The most updates this viewer ever had waiting. */
    synchronized int maxPending() {
        return maxPending;
    }

    @Override
    protected void exited(String why) {
        synchronized (this) {
            closed = true;
            pending.clear();
            notifyAll();
        }
        coordinator.removeViewer(this, why);
    }
}
