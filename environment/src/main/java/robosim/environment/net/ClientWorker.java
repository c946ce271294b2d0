package robosim.environment.net;

import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.Challenge;
import robosim.protocol.Limits;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Proof;
import robosim.protocol.ProtocolException;
import robosim.protocol.SimulationKeys;

/**
 * One connected client, served by one named thread. The base class owns the connection's life and
 * the one failure policy: a protocol fault or a broken connection drops this client with a logged
 * reason; the simulation goes on. Until its hello is accepted ({@link #handshakeDone}) a client is a
 * stranger: it may send at most {@link Limits#MAX_HELLO_BYTES} per message. Its {@link ConnectionClock}
 * runs from its arrival: the {@link ConnectionWatch} cuts it off if its hello (and proof) are not in by the
 * handshake deadline, however slowly its bytes trickle in ({@link #heardHello}), or if it does not take a
 * write within the write timeout, whoever writes to it.
 */
abstract class ClientWorker implements Runnable, ConnectionWatch.Watched {
    private static final Logger LOG = LoggerFactory.getLogger(ClientWorker.class);

    protected final ClientWorkerCoordinator coordinator;
    private final Socket socket;
    private volatile String name;
    protected volatile ObjectConnection connection;
    private Runnable release = () -> { };
    /** Its clocks, from its arrival (the accept thread makes it). */
    protected final ConnectionClock clock;

    ClientWorker(ClientWorkerCoordinator coordinator, Socket socket, String name) {
        this.coordinator = coordinator;
        this.socket = socket;
        this.name = name;
        Settings settings = coordinator.settings();
        this.clock = new ConnectionClock(settings.handshakeTimeoutMs(), settings.writeTimeoutMs());
    }

    final void start() {
        Thread t = new Thread(this, name);
        t.setDaemon(true);
        t.setUncaughtExceptionHandler((th, e) -> LOG.error("{} failed", th.getName(), e));
        t.start();
    }

    /**
     * Accept thread, before {@link #start}: {@code onClose} runs once when the connection is closed (it frees
     * the port's place); the {@link ConnectionWatch} times it from now on.
     */
    final void admit(Runnable onClose) {
        this.release = onClose;
        coordinator.watch().watch(this);
    }

    @Override
    public final ConnectionClock clock() {
        return clock;
    }

    @Override
    public final String label() {
        return name;
    }

    /**
     * Right after the client's hello: with a shared secret, challenges it (a fresh nonce) and reads its
     * proof, still under the handshake deadline and the stranger's byte cap; then stops the handshake
     * clock (what follows, the loop's verdict, is the Environment's own time, not the client's). Null if
     * the client proved the secret for {@code role} (or there is none), else the refusal.
     */
    protected final String heardHello(String role) throws IOException {
        String refusal = proveSecret(role);
        stopHandshakeClock();
        return refusal;
    }

    /**
     * With a shared secret, challenges the client (a fresh nonce) and reads its proof, under the handshake
     * deadline and the stranger's byte cap: null if it proved the secret for {@code role} (or there is none),
     * else the refusal.
     */
    protected final String proveSecret(String role) throws IOException {
        SimulationKeys secret = coordinator.settings().keys();
        if (secret == null) {
            return null;
        }
        byte[] nonce = SimulationKeys.nonce();
        connection.write(new Challenge(nonce));
        connection.flush();
        Proof proof = connection.read(Proof.class);
        return secret.proves(role, nonce, proof.mac()) ? null : "it did not prove the shared secret";
    }

    /** The client's hello is all in: the handshake deadline no longer applies (or it has already cut it off). */
    protected final void stopHandshakeClock() throws IOException {
        if (!clock.handshakeOver()) {
            throw new IOException(clock.cutOffReason()); // (the deadline closed the connection just before)
        }
    }

    /** Writes one message on this connection's write clock: a client that does not take it in time is cut off. */
    protected final void send(java.io.Externalizable message) throws IOException {
        clock.writing();
        try {
            connection.write(message);
            connection.flush();
        } finally {
            clock.written();
        }
    }

    /** This client's hello is accepted: from now on its messages may take up to {@link Limits#MAX_MESSAGE_BYTES}. */
    protected final void handshakeDone() {
        connection.limitMessageBytes(Limits.MAX_MESSAGE_BYTES);
    }

    /** Logs that this client was refused, and why (network text escaped). */
    protected final void logRefused(String why) {
        LOG.warn("{} refused: {}", name, Printable.of(why));
    }

    protected final String name() {
        return name;
    }

    /** Renames the worker and its thread once the client has said who it is. */
    protected final void rename(String newName) {
        name = newName;
        Thread.currentThread().setName(newName);
    }

    @Override
    public final void run() {
        String why = "finished";
        try {
            configure(socket);
            ObjectConnection c = ObjectConnection.server(socket, coordinator.settings().resetEvery(),
                    coordinator.settings().keys());
            c.limitMessageBytes(Limits.MAX_HELLO_BYTES);
            connection = c;
            if (dropped) {
                c.close(); // dropped (cut off) while the streams were being opened
            }
            serve();
        } catch (IOException e) {
            why = failed(e);
        } catch (InterruptedException e) {
            why = "interrupted";
            Thread.currentThread().interrupt();
        } finally {
            coordinator.watch().forget(this);
            if (connection != null) {
                connection.close();
            } else {
                try {
                    socket.close();
                } catch (IOException ignored) {
                    // already gone
                }
            }
            release.run();
            exited(why);
        }
    }

    /** Why the session ended on {@code e}, logged: a protocol fault or a missed deadline is a warning. */
    private String failed(IOException e) {
        String why;
        if (clock.cutOffReason() != null) {
            why = clock.cutOffReason();
            LOG.debug("{}: {}", name, why); // (the watch has said it)
        } else if (e instanceof ProtocolException) {
            why = e.getMessage();
            LOG.warn("{} dropped: {}", name, Printable.of(why));
        } else if (e instanceof EOFException) {
            why = "the client closed the connection";
            LOG.debug("{}: {}", name, why);
        } else {
            why = "connection lost: " + e.getMessage();
            LOG.info("{}: {}", name, Printable.of(why));
        }
        return why;
    }

    /**
     * Waits for the loop's answer to this client's hello, at most {@link #VERDICT_LIMIT_MS}; a loop that
     * does not answer in that time (it never blocks that long) is taken as a refusal.
     */
    protected final <T> T awaitVerdict(java.util.concurrent.CompletableFuture<T> verdict)
            throws IOException, InterruptedException {
        try {
            return verdict.get(VERDICT_LIMIT_MS, java.util.concurrent.TimeUnit.MILLISECONDS);
        } catch (java.util.concurrent.TimeoutException e) {
            throw new IOException("the Environment did not answer its hello in time");
        } catch (java.util.concurrent.ExecutionException e) {
            throw new IOException("its hello was not answered: " + e.getCause());
        }
    }

    private static final long VERDICT_LIMIT_MS = 30_000;

    /** True once {@link #drop} has been called. */
    final boolean dropped() {
        return dropped;
    }

    private volatile boolean dropped;

    /** Closes the connection, so this worker's blocked read or write ends. Any thread. */
    @Override
    public final void drop() {
        dropped = true;
        ObjectConnection c = connection;
        if (c != null) {
            c.close();
        } else {
            try {
                socket.close();
            } catch (IOException ignored) {
                // already gone
            }
        }
    }

    /** Socket options for this kind of client, set before the streams are opened. */
    protected void configure(Socket s) throws IOException {
    }

    /** The client's whole session; returns or throws when it is over. */
    protected abstract void serve() throws IOException, InterruptedException;

    /** Called once, on this worker's thread, after the connection is closed. */
    protected abstract void exited(String why);
}
