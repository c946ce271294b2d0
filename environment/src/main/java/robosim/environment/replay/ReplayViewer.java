package robosim.environment.replay;

import java.io.EOFException;
import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.Printable;
import robosim.environment.net.ViewerQueue;
import robosim.environment.net.ViewerSink;
import robosim.environment.net.ConnectionClock;
import robosim.environment.net.ConnectionWatch;
import robosim.environment.net.Port;
import robosim.environment.net.ViewerWrites;
import robosim.protocol.Challenge;
import robosim.protocol.GeometryHello;
import robosim.protocol.Limits;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Proof;
import robosim.protocol.Protocol;
import robosim.protocol.ProtocolException;
import robosim.protocol.SimulationEnd;
import robosim.protocol.SimulationKeys;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * One viewer of a replay, on its own thread {@code replay-viewer[n]}, speaking the viewer protocol exactly
 * as the Environment's viewer worker does: its hello (and, with keys, the shared secret's proof) under the
 * handshake deadline and the stranger's byte cap, then the snapshot the {@link ReplayClock} hands it, then
 * what its {@link ViewerQueue} holds until the end. A fault drops this viewer with a logged reason; the
 * replay goes on.
 */
final class ReplayViewer implements ViewerSink, ConnectionWatch.Watched, Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(ReplayViewer.class);
    /** As the Environment's viewer worker: a viewer that stops reading blocks this thread after this much. */
    static final int SEND_BUFFER_BYTES = 64 * 1024;
    /** What this port is, for a client that speaks another protocol. */
    private static final String DESCRIPTION = "a replay's viewer port";
    private static final long JOIN_LIMIT_MS = 30_000;

    private final Socket socket;
    private final String name;
    private final ReplayClock clock;
    private final SimulationKeys keys;
    private final int resetEvery;
    private final Runnable release;
    private final ConnectionClock connectionClock;
    private final ConnectionWatch watch;
    private final CountDownLatch done = new CountDownLatch(1);
    private volatile ObjectConnection connection;
    private volatile ViewerQueue queue;
    private volatile ViewerWrites writes;
    private volatile boolean joined;
    private final List<String> robots;

    ReplayViewer(Socket socket, int serial, ReplayClock clock, List<String> robots, SimulationKeys keys, int resetEvery,
            ConnectionClock connectionClock, ConnectionWatch watch, Runnable release) {
        this.connectionClock = connectionClock;
        this.watch = watch;
        this.socket = socket;
        this.robots = robots;
        this.name = "replay-viewer[" + serial + "]";
        this.clock = clock;
        this.keys = keys;
        this.resetEvery = resetEvery;
        this.release = release;
    }

    @Override
    public ConnectionClock clock() {
        return connectionClock;
    }

    @Override
    public String label() {
        return name;
    }

    @Override
    public void run() {
        String why = "finished";
        try {
            socket.setSendBufferSize(SEND_BUFFER_BYTES);
            connection = ObjectConnection.server(socket, resetEvery, keys, DESCRIPTION);
            writes = new ViewerWrites(connection, connectionClock);
            connection.limitMessageBytes(Limits.MAX_HELLO_BYTES);
            serve();
        } catch (IOException e) {
            why = connectionClock.cutOffReason() != null ? connectionClock.cutOffReason()
                    : e instanceof EOFException ? "the viewer closed the connection" : e.getMessage();
            LOG.info("{}: {}", name, Printable.of(why));
        } catch (InterruptedException e) {
            why = "interrupted";
            Thread.currentThread().interrupt();
        } finally {
            watch.forget(this);
            drop();
            release.run();
            ViewerQueue q = queue;
            if (q != null) {
                q.close();
            }
            if (joined) {
                clock.left(this, why);
            }
            done.countDown();
        }
    }

    private void serve() throws IOException, InterruptedException {
        Externalizable said = connection.readOneOf(Externalizable.class, Port.HELLOS);
        if (!(said instanceof ViewerHello hello)) {
            String why = "that is a replay's viewer port (a recording played back); "
                    + (said instanceof GeometryHello ? "Geometry connects" : "robots connect") + " to a live Environment";
            writes.send(new SimulationEnd(-1, why));
            throw new ProtocolException("a " + said.getClass().getSimpleName() + " on " + DESCRIPTION + "; told it: "
                    + why);
        }
        String refusal = null;
        if (keys != null) {
            byte[] nonce = SimulationKeys.nonce();
            connection.write(new Challenge(nonce));
            connection.flush();
            refusal = keys.proves("viewer", nonce, connection.read(Proof.class).mac()) ? null
                    : "it did not prove the shared secret";
        }
        if (!connectionClock.handshakeOver()) {
            throw new IOException(connectionClock.cutOffReason());
        }
        if (refusal == null && hello.protocolVersion() != Protocol.VERSION) {
            refusal = "protocol version " + hello.protocolVersion() + " is not supported (this replay speaks "
                    + Protocol.VERSION + ")";
        }
        int watched = hello.watch().isEmpty() ? -1 : robots.indexOf(hello.watch());
        if (refusal == null && watched < 0 && !hello.watch().isEmpty()) {
            refusal = "it would watch \"" + Printable.of(hello.watch(), 64) + "\", which is not a robot of this "
                    + "recording";
        }
        if (refusal != null) {
            LOG.warn("{} refused: {}", name, Printable.of(refusal));
            writes.send(new SimulationEnd(-1, refusal));
            return;
        }
        connection.limitMessageBytes(Limits.MAX_MESSAGE_BYTES);
        ViewerQueue q = new ViewerQueue(hello.everyStep(), hello.maxUpdatesPerSecond());
        q.watch(watched);
        queue = q;
        WorldSnapshot first;
        try {
            joined = true;
            first = clock.join(this).get(JOIN_LIMIT_MS, TimeUnit.MILLISECONDS);
        } catch (ExecutionException | TimeoutException e) {
            throw new ProtocolException("the replay did not take this viewer: " + (e.getCause() == null ? e : e.getCause()));
        }
        writes.serve(first, queue, clock::roomFreed);
    }

    @Override
    public ViewerQueue queue() {
        return queue;
    }

    @Override
    public String viewerName() {
        return name;
    }

    @Override
    public void drop() {
        ObjectConnection c = connection;
        if (c != null) {
            c.close();
        }
        try {
            socket.close();
        } catch (IOException ignored) {
            // already gone
        }
    }

    @Override
    public boolean awaitDone(long nanos) throws InterruptedException {
        return done.await(nanos, TimeUnit.NANOSECONDS);
    }
}
