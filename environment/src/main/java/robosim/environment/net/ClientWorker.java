package robosim.environment.net;

import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.net.SocketTimeoutException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.ObjectConnection;
import robosim.protocol.ProtocolException;

/**
 * One connected client, served by one named thread. The base class owns the connection's life and
 * the one failure policy: a protocol fault or a broken connection drops this client with a logged
 * reason; the simulation goes on.
 */
abstract class ClientWorker implements Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(ClientWorker.class);

    protected final ClientWorkerCoordinator coordinator;
    private final Socket socket;
    private volatile String name;
    protected volatile ObjectConnection connection;

    ClientWorker(ClientWorkerCoordinator coordinator, Socket socket, String name) {
        this.coordinator = coordinator;
        this.socket = socket;
        this.name = name;
    }

    final void start() {
        Thread t = new Thread(this, name);
        t.setDaemon(true);
        t.setUncaughtExceptionHandler((th, e) -> LOG.error("{} failed", th.getName(), e));
        t.start();
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
            socket.setSoTimeout(coordinator.settings().handshakeTimeoutMs());
            configure(socket);
            connection = new ObjectConnection(socket, coordinator.settings().resetEvery());
            serve();
        } catch (SocketTimeoutException e) {
            why = "timed out waiting for the client";
            LOG.warn("{} dropped: {}", name, Printable.of(why));
        } catch (ProtocolException e) {
            why = e.getMessage();
            LOG.warn("{} dropped: {}", name, Printable.of(why));
        } catch (EOFException e) {
            why = "the client closed the connection";
            LOG.debug("{}: {}", name, Printable.of(why));
        } catch (IOException e) {
            why = "connection lost: " + e.getMessage();
            LOG.info("{}: {}", name, Printable.of(why));
        } catch (InterruptedException e) {
            why = "interrupted";
            Thread.currentThread().interrupt();
        } finally {
            if (connection != null) {
                connection.close();
            } else {
                try {
                    socket.close();
                } catch (IOException ignored) {
                    // already gone
                }
            }
            exited(why);
        }
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
