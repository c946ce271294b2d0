package robosim.environment.server;

import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A server's listening sockets, their {@code accept-*} threads ({@code accept-robots}, {@code accept-viewers},
 * {@code accept-geometry}), which hand each accepted socket to a new worker thread, and the cap on the
 * connections each port holds at once (one more is closed at once, with a logged line at most once a second per
 * port), and on what clients not yet accepted hold (the {@link StrangerBudget}). Each connection's handshake
 * deadline runs from here, on its {@link ConnectionClock}, timed by the context's {@link ConnectionWatch}, which
 * {@link #accept} starts and {@link #close} lets end once its last connection has.
 */
public final class Acceptors {
    private static final Logger LOG = LoggerFactory.getLogger(Acceptors.class);

    /** Makes the worker that serves a connection accepted on a port; {@code serial} numbers the server's connections. */
    public interface Workers {
        ClientWorker serve(Socket socket, int serial);
    }

    /** One bound port: its socket, its cap and what serves its connections. */
    private static final class Listening {
        final Port port;
        final ServerSocket socket;
        final int cap;
        final Workers workers;
        final AtomicInteger open = new AtomicInteger();
        /** accept thread only */
        long lastLogNanos;
        int refusedSinceLog;

        Listening(Port port, ServerSocket socket, int cap, Workers workers) {
            this.port = port;
            this.socket = socket;
            this.cap = cap;
            this.workers = workers;
        }
    }

    private final ServerContext context;
    private final InetAddress bind;
    private final int backlog;
    private final Map<Port, Listening> ports = new EnumMap<>(Port.class);
    private final List<Thread> acceptors = new ArrayList<>();
    private final AtomicInteger serial = new AtomicInteger();

    /** {@code backlog}: connections the system queues on each port before they are accepted. */
    public Acceptors(ServerContext context, InetAddress bind, int backlog) {
        this.context = context;
        this.bind = bind;
        this.backlog = backlog;
    }

    /**
     * Binds {@code port} at {@code number} (0: a free one), to hold at most {@code cap} connections at once, each
     * served by {@code workers}. One in use is a {@link BindException} naming it, and nothing bound so far stays
     * bound. Listens through a blocking {@link ServerSocketChannel}: the sockets it accepts read with one system
     * call per blocking read (see {@link robosim.protocol.Connector}).
     */
    public void bind(Port port, int number, int cap, Workers workers) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        // a later simulation of the same Environment listens on the same port at once
        channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
        ServerSocket s = channel.socket();
        try {
            s.bind(new InetSocketAddress(bind, number), backlog);
        } catch (BindException e) {
            channel.close();
            close();
            throw new BindException(port.word() + " port " + number + " is already in use");
        }
        ports.put(port, new Listening(port, s, cap, workers));
    }

    /** Starts the connection watch and one {@code accept-*} thread per bound port. */
    public void accept() {
        context.watch().start();
        for (Listening l : ports.values()) {
            Thread t = new Thread(() -> acceptLoop(l), "accept-" + l.port.word()
                    + (l.port == Port.GEOMETRY ? "" : "s"));
            t.setDaemon(true);
            acceptors.add(t);
            t.start();
        }
    }

    private void acceptLoop(Listening l) {
        ServerSocket server = l.socket;
        while (!server.isClosed()) {
            try {
                Socket s = server.getChannel().accept().socket();
                if (l.open.incrementAndGet() > l.cap) {
                    l.open.decrementAndGet();
                    s.close();
                    refused(l, "it holds at most " + l.cap + " at a time (--max-connections)");
                    continue;
                }
                if (context.strangers().full()) {
                    l.open.decrementAndGet();
                    s.close();
                    refused(l, "clients not yet accepted hold all the Environment keeps for them ("
                            + (context.strangers().total() >> 20) + " MiB)");
                    continue;
                }
                ClientWorker w = null;
                try {
                    w = l.workers.serve(s, serial.incrementAndGet());
                    w.admit(l.open::decrementAndGet);
                    w.start();
                } catch (RuntimeException | OutOfMemoryError e) { // out of threads
                    if (w != null) {
                        context.watch().forget(w);
                    }
                    l.open.decrementAndGet();
                    s.close();
                    if (!server.isClosed()) {
                        LOG.warn("{}: could not serve a connection: {}", Thread.currentThread().getName(), e.toString());
                    }
                }
            } catch (IOException e) {
                if (!server.isClosed()) {
                    LOG.warn("{}: accept failed: {}", Thread.currentThread().getName(), e.getMessage());
                    LockSupport.parkNanos(100_000_000L); // back off: e.g. out of file descriptors
                }
            }
        }
    }

    /** A connection was closed at once, for {@code why}: says so at most once a second per port. */
    private static void refused(Listening l, String why) {
        l.refusedSinceLog++;
        long now = System.nanoTime();
        if (now - l.lastLogNanos >= TimeUnit.SECONDS.toNanos(1) || l.lastLogNanos == 0) {
            LOG.warn("{} port: {} connection(s) closed at once: {}", l.port.word(), l.refusedSinceLog, why);
            l.refusedSinceLog = 0;
            l.lastLogNanos = now;
        }
    }

    /** The number {@code port} is bound to, or -1 if it is not listening. */
    public int port(Port port) {
        Listening l = ports.get(port);
        return l == null ? -1 : l.socket.getLocalPort();
    }

    /** Closes every listening socket; the connection watch ends once the connections it times have. */
    public void close() {
        for (Listening l : ports.values()) {
            try {
                l.socket.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
        context.watch().stopWhenIdle();
    }

    /** Closes the sockets and waits until the accept threads have left them, so the ports are free. */
    public void awaitClosed(long timeoutMs) throws InterruptedException {
        close();
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        for (Thread t : acceptors) {
            t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
        }
    }
}
