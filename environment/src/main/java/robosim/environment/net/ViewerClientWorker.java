package robosim.environment.net;

import robosim.protocol.Printable;
import java.io.IOException;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import robosim.protocol.Protocol;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * Serves one viewer from its own thread, {@code viewer-worker[n]}: the snapshot, then what its
 * {@link ViewerQueue} holds (updates, run states, the end). The loop only offers to the queue, never
 * writes to this socket; a viewer that does not take a write within the write timeout is cut off by the
 * {@link ConnectionWatch}, and this worker then tells the loop it has gone.
 */
final class ViewerClientWorker extends ClientWorker implements ViewerSink {
    /**
     * Kernel send buffer for a viewer: enough for dozens of updates, so a live viewer never waits on
     * it, while a viewer that stops reading blocks its worker after this much instead of after the
     * megabytes loopback would otherwise allow.
     */
    static final int SEND_BUFFER_BYTES = 64 * 1024;

    private final CountDownLatch done = new CountDownLatch(1);
    private volatile ViewerQueue queue;

    ViewerClientWorker(ClientWorkerCoordinator coordinator, Socket socket, int serial) {
        super(coordinator, socket, "viewer-worker[" + serial + "]", Port.VIEWER);
    }

    @Override
    protected void configure(Socket s) throws IOException {
        s.setSendBufferSize(SEND_BUFFER_BYTES);
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        ViewerWrites writes = new ViewerWrites(connection, clock);
        ViewerHello hello = (ViewerHello) handshake.hello(port, coordinator.ports());
        String refusal = handshake.heard("viewer");
        if (refusal == null && hello.protocolVersion() != Protocol.VERSION) {
            refusal = "protocol version " + hello.protocolVersion() + " is not supported (the Environment "
                    + "speaks " + Protocol.VERSION + ")";
        }
        int watched = refusal == null ? watched(hello.watch()) : -1;
        if (refusal == null && watched == NO_SUCH_ROBOT) {
            refusal = "it would watch \"" + Printable.of(hello.watch(), 64) + "\", which is not a robot of this "
                    + "simulation";
        }
        if (refusal != null) {
            handshake.refused(refusal);
            writes.send(new SimulationEnd(-1, refusal));
            return;
        }
        ViewerQueue q = new ViewerQueue(hello.everyStep(), hello.maxUpdatesPerSecond());
        q.watch(watched);
        queue = q;
        CompletableFuture<WorldSnapshot> snapshot = new CompletableFuture<>();
        coordinator.post(new LoopEvent.ViewerJoins(this, snapshot));
        WorldSnapshot first = handshake.verdict(snapshot);
        handshake.accepted();
        writes.serve(first, queue, () -> coordinator.post(new LoopEvent.ViewerHasRoom(this)));
    }

    private static final int NO_SUCH_ROBOT = -2;

    /** The index of the robot named {@code name}; -1 for none asked ("" ), {@link #NO_SUCH_ROBOT} if there is none by that name. */
    private int watched(String name) {
        if (name.isEmpty()) {
            return -1;
        }
        int i = coordinator.spec().indexOf(name);
        if (i < 0) { // (a robot that joined the running world: the loop's published list has it)
            List<RobotState> now = coordinator.status().states();
            for (int k = 0; k < now.size() && i < 0; k++) { // (an added robot not there yet has no place)
                i = now.get(k).name().equals(name) && !RobotState.ADDED.equals(now.get(k).state()) ? k : -1;
            }
        }
        return i < 0 ? NO_SUCH_ROBOT : i;
    }

    /** Its queue, once it has said hello (the loop only sees joined viewers). */
    @Override
    public ViewerQueue queue() {
        return queue;
    }

    @Override
    public String viewerName() {
        return name();
    }

    @Override
    public boolean awaitDone(long nanos) throws InterruptedException {
        return done.await(nanos, TimeUnit.NANOSECONDS);
    }

    /** Any thread, once the run is over: no longer one of its viewers. */
    void leftAfterTheRun(String why) {
        coordinator.viewerLeft(this, why);
    }

    @Override
    protected void exited(String why) {
        ViewerQueue q = queue;
        if (q != null) {
            q.close();
            coordinator.post(new LoopEvent.ViewerLeaves(this, why, clock.cutOffReason() != null));
        }
        done.countDown();
    }
}
