package robosim.environment.server;

import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import robosim.protocol.Printable;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * Serves one viewer from its own thread ({@code viewer-worker[n]} of the Environment, {@code replay-viewer[n]} of a
 * replay), the same for whoever publishes to it ({@link ViewerHost}): the handshake, the snapshot the host hands it,
 * then what its {@link ViewerQueue} holds (updates, run states, the end), each write on the connection's clock. The
 * host only offers to the queue, never writes to this socket; a viewer that does not take a write within the write
 * timeout is cut off by the {@link ConnectionWatch}, and this worker then tells the host it has gone.
 */
public final class ViewerClientWorker extends ClientWorker implements ViewerSink {
    /**
     * Kernel send buffer for a viewer: enough for dozens of updates, so a live viewer never waits on
     * it, while a viewer that stops reading blocks its worker after this much instead of after the
     * megabytes loopback would otherwise allow.
     */
    static final int SEND_BUFFER_BYTES = 64 * 1024;

    private final ViewerHost host;
    private final CountDownLatch done = new CountDownLatch(1);
    private volatile ViewerQueue queue;

    public ViewerClientWorker(ServerContext context, Socket socket, String name, ViewerHost host) {
        super(context, socket, name, Port.VIEWER);
        this.host = host;
    }

    @Override
    protected void configure(Socket s) throws IOException {
        s.setSendBufferSize(SEND_BUFFER_BYTES);
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        ViewerHello hello = (ViewerHello) handshake.hello(port);
        String refusal = handshake.heard("viewer");
        if (refusal == null) {
            refusal = handshake.version(hello.protocolVersion());
        }
        int watched = refusal != null || hello.watch().isEmpty() ? -1 : host.robot(hello.watch());
        if (refusal == null && watched < 0 && !hello.watch().isEmpty()) {
            refusal = "it would watch \"" + Printable.of(hello.watch(), 64) + "\", which is not a robot of "
                    + host.world();
        }
        if (refusal != null) {
            handshake.refused(refusal);
            send(new SimulationEnd(-1, refusal));
            return;
        }
        ViewerQueue q = new ViewerQueue(hello.everyStep(), hello.maxUpdatesPerSecond(), System::nanoTime);
        q.watch(watched);
        queue = q;
        WorldSnapshot first = handshake.verdict(host.join(this));
        handshake.accepted();
        send(first);
        while (true) {
            Object next = q.take();
            if (q.claimRoomSignal()) {
                host.roomFreed(this);
            }
            send((Externalizable) next);
            if (next instanceof SimulationEnd) {
                return;
            }
        }
    }

    /** Its queue, once it has said hello (the host only sees joined viewers). */
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

    @Override
    protected void exited(String why) {
        ViewerQueue q = queue;
        if (q != null) {
            q.close();
            host.left(this, why, clock.cutOffReason() != null);
        }
        done.countDown();
    }
}
