package robosim.environment.net;

import java.io.IOException;
import java.net.BindException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Function;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The listening sockets (robots, viewers, and Geometry unless it is in-process), their {@code accept-*}
 * threads, which hand each accepted socket to a new worker thread, and the cap on the connections each
 * port holds at once (one more is closed at once, with a logged line at most once a second per port). Each
 * connection's handshake deadline runs from here, on its {@link ConnectionClock}.
 */
final class Acceptors {
    private static final Logger LOG = LoggerFactory.getLogger(Acceptors.class);

    /** One port's connections, against its cap. */
    private static final class Held {
        final String what;
        final int cap;
        final AtomicInteger open = new AtomicInteger();
        /** accept thread only */
        long lastLogNanos;
        int refusedSinceLog;

        Held(String what, int cap) {
            this.what = what;
            this.cap = cap;
        }
    }

    private final ClientWorkerCoordinator coordinator;
    private final List<ServerSocket> servers = new ArrayList<>();
    private final List<Thread> acceptors = new ArrayList<>();
    private int serial;

    Acceptors(ClientWorkerCoordinator coordinator) {
        this.coordinator = coordinator;
    }

    /** Binds every port; one in use is a {@link BindException} naming it (and nothing stays bound). */
    void bind() throws IOException {
        Settings s = coordinator.settings();
        bind("robot", s.robotPort());
        bind("viewer", s.viewerPort());
        if (!s.inProcessGeometry()) {
            bind("geometry", s.geometryPort());
        }
    }

    /**
     * Listens through a blocking {@link ServerSocketChannel}: the sockets it accepts read with one system
     * call per blocking read (see {@link robosim.protocol.Connector}).
     */
    private void bind(String what, int port) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        // a later simulation of the same Environment listens on the same port at once
        channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
        ServerSocket s = channel.socket();
        try {
            s.bind(new InetSocketAddress(coordinator.settings().bind(), port), 1024);
        } catch (BindException e) {
            channel.close();
            close();
            throw new BindException(what + " port " + port + " is already in use");
        }
        servers.add(s);
    }

    /** Starts one {@code accept-*} thread per listening socket. */
    void accept() {
        int cap = coordinator.settings().maxConnections();
        int robots = coordinator.spec().robots().size() + coordinator.spec().joinable(); // (and its join rules')
        acceptOn(servers.get(0), new Held("robot", robots + cap),
                s -> new RobotClientWorker(coordinator, s, ++serial));
        acceptOn(servers.get(1), new Held("viewer", cap), s -> new ViewerClientWorker(coordinator, s, ++serial));
        if (servers.size() > 2) {
            acceptOn(servers.get(2), new Held("geometry", cap), s -> new GeometryClientWorker(coordinator, s));
        }
    }

    private void acceptOn(ServerSocket server, Held held, Function<Socket, ClientWorker> factory) {
        String threadName = "accept-" + held.what + (held.what.equals("geometry") ? "" : "s");
        Thread t = new Thread(() -> {
            while (!server.isClosed()) {
                try {
                    Socket s = server.getChannel().accept().socket();
                    if (held.open.incrementAndGet() > held.cap) {
                        held.open.decrementAndGet();
                        s.close();
                        refused(held, "it holds at most " + held.cap + " at a time (--max-connections)");
                        continue;
                    }
                    if (coordinator.strangers().full()) {
                        held.open.decrementAndGet();
                        s.close();
                        refused(held, "clients not yet accepted hold all the Environment keeps for them ("
                                + (coordinator.strangers().total() >> 20) + " MiB)");
                        continue;
                    }
                    ClientWorker w = null;
                    try {
                        synchronized (this) {
                            w = factory.apply(s);
                        }
                        w.admit(held.open::decrementAndGet);
                        w.start();
                    } catch (RuntimeException | OutOfMemoryError e) { // out of threads
                        if (w != null) {
                            coordinator.watch().forget(w);
                        }
                        held.open.decrementAndGet();
                        s.close();
                        if (!server.isClosed()) {
                            LOG.warn("{}: could not serve a connection: {}", threadName, e.toString());
                        }
                    }
                } catch (IOException e) {
                    if (!server.isClosed()) {
                        LOG.warn("{}: accept failed: {}", threadName, e.getMessage());
                        LockSupport.parkNanos(100_000_000L); // back off: e.g. out of file descriptors
                    }
                }
            }
        }, threadName);
        t.setDaemon(true);
        acceptors.add(t);
        t.start();
    }

    /** A connection was closed at once, for {@code why}: says so at most once a second per port. */
    private static void refused(Held held, String why) {
        held.refusedSinceLog++;
        long now = System.nanoTime();
        if (now - held.lastLogNanos >= TimeUnit.SECONDS.toNanos(1) || held.lastLogNanos == 0) {
            LOG.warn("{} port: {} connection(s) closed at once: {}", held.what, held.refusedSinceLog, why);
            held.refusedSinceLog = 0;
            held.lastLogNanos = now;
        }
    }

    /** The bound ports: robot, viewer, geometry (-1 when geometry is in-process). */
    int[] ports() {
        return new int[] {servers.get(0).getLocalPort(), servers.get(1).getLocalPort(),
            servers.size() > 2 ? servers.get(2).getLocalPort() : -1};
    }

    void close() {
        for (ServerSocket s : servers) {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
    }

    /** Closes the sockets and waits until the accept threads have left them, so the ports are free. */
    void awaitClosed(long timeoutMs) throws InterruptedException {
        close();
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        for (Thread t : acceptors) {
            t.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
        }
    }
}
