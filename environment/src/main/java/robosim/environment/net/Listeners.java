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
import java.util.concurrent.locks.LockSupport;
import java.util.function.Function;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The listening sockets (robots, viewers, and Geometry unless it is in-process) and their
 * {@code accept-*} threads, which hand each accepted socket to a new worker thread.
 */
final class Listeners {
    private static final Logger LOG = LoggerFactory.getLogger(Listeners.class);

    private final ClientWorkerCoordinator coordinator;
    private final List<ServerSocket> servers = new ArrayList<>();
    private final List<Thread> acceptors = new ArrayList<>();
    private int serial;

    Listeners(ClientWorkerCoordinator coordinator) {
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
        acceptOn(servers.get(0), "accept-robots", s -> new RobotClientWorker(coordinator, s, ++serial));
        acceptOn(servers.get(1), "accept-viewers", s -> new ViewerClientWorker(coordinator, s, ++serial));
        if (servers.size() > 2) {
            acceptOn(servers.get(2), "accept-geometry", s -> new GeometryClientWorker(coordinator, s));
        }
    }

    private void acceptOn(ServerSocket server, String threadName, Function<Socket, ClientWorker> factory) {
        Thread t = new Thread(() -> {
            while (!server.isClosed()) {
                try {
                    Socket s = server.getChannel().accept().socket();
                    ClientWorker w;
                    synchronized (this) {
                        w = factory.apply(s);
                    }
                    w.start();
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
