package robosim.environment.server;

import robosim.protocol.Printable;
import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.ObjectConnection;
import robosim.protocol.ProtocolException;

/**
 * One connected client, served by one named thread. The base class owns the connection's life and
 * the one failure policy: a protocol fault or a broken connection drops this client with a logged
 * reason; the simulation goes on. Until its {@link Handshake} accepts it a client is a stranger. Its
 * {@link ConnectionClock} runs from its arrival: the {@link ConnectionWatch} cuts it off if its hello (and
 * proof) are not in by the handshake deadline, however slowly its bytes trickle in, or if it does not take a
 * write within the write timeout, whoever writes to it.
 */
public abstract class ClientWorker implements Runnable, ConnectionWatch.Watched {
    private static final Logger LOG = LoggerFactory.getLogger(ClientWorker.class);

    /** What this connection is served with. */
    protected final ServerContext context;
    private final Socket socket;
    private volatile String name;
    protected volatile ObjectConnection connection;
    /** Its handshake, once the connection's streams are open. */
    protected Handshake handshake;
    private Runnable release = () -> { };
    /** The port it came to. */
    protected final Port port;
    /** Its clocks, from its arrival (the accept thread makes it). */
    protected final ConnectionClock clock;

    protected ClientWorker(ServerContext context, Socket socket, String name, Port port) {
        this.context = context;
        this.port = port;
        this.socket = socket;
        this.name = name;
        this.clock = new ConnectionClock(context.handshakeTimeoutMs(), context.writeTimeoutMs());
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
        context.watch().watch(this);
    }

    @Override
    public final ConnectionClock clock() {
        return clock;
    }

    @Override
    public final String label() {
        return name;
    }

    /** Writes one message on this connection's write clock: a client that does not take it in time is cut off. */
    public final void send(java.io.Externalizable message) throws IOException {
        clock.writing();
        try {
            connection.write(message);
            connection.flush();
        } finally {
            clock.written();
        }
    }

    protected final String name() {
        return name;
    }

    /** Renames the worker and its thread once the client has said who it is. */
    public final void rename(String newName) {
        name = newName;
        Thread.currentThread().setName(newName);
    }

    @Override
    public final void run() {
        String why = "finished";
        try {
            configure(socket);
            ObjectConnection c = ObjectConnection.server(socket, context.resetEvery(), context.keys(),
                    context.guide().description(port));
            handshake = new Handshake(this, c, context);
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
            context.watch().forget(this);
            if (handshake != null) {
                handshake.end();
            }
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
            LOG.warn("{} dropped: {}", name, Printable.of(why, Handshake.LOGGED_CHARS));
        } else if (e instanceof EOFException) {
            why = "the client closed the connection";
            LOG.debug("{}: {}", name, why);
        } else {
            why = "connection lost: " + e.getMessage();
            LOG.info("{}: {}", name, Printable.of(why, Handshake.LOGGED_CHARS));
        }
        return why;
    }

    /** True once {@link #drop} has been called. */
    public final boolean dropped() {
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
