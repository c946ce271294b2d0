package robosim.environment.replay;

import java.io.Closeable;
import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.net.ConnectionClock;
import robosim.environment.net.ConnectionWatch;
import robosim.protocol.SimulationKeys;

/**
 * A replay's viewer port: the {@code accept-viewers} thread hands each connection to a new
 * {@link ReplayViewer}, with the bounds the Environment's ports have: at most {@code maxConnections} at
 * once (one more is closed at once, logged at most once a second), and the same {@link ConnectionWatch}:
 * each viewer's handshake deadline from its arrival, however slowly a stranger's bytes trickle in, and its
 * write timeout.
 */
final class ReplayPort implements Closeable {
    private static final Logger LOG = LoggerFactory.getLogger(ReplayPort.class);

    private final ServerSocket server;
    private final ReplayClock clock;
    private final SimulationKeys keys;
    private final int maxConnections;
    private final int handshakeMs;
    private final long writeMs;
    private final ConnectionWatch watch;
    private final int resetEvery;
    private final AtomicInteger open = new AtomicInteger();
    /** The recorded robots' names, world order: what a viewer may watch. */
    private final List<String> robots;
    private long lastRefusalLog;
    private int serial;

    /** Binds {@code port} on {@code bind}; a port in use is a {@link BindException} naming it. */
    ReplayPort(InetAddress bind, int port, ReplayClock clock, List<String> robots, SimulationKeys keys,
            int maxConnections, int handshakeMs, long writeMs, int resetEvery) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
        try {
            channel.socket().bind(new InetSocketAddress(bind, port), 256);
        } catch (BindException e) {
            channel.close();
            throw new BindException("viewer port " + port + " is already in use");
        }
        this.server = channel.socket();
        this.clock = clock;
        this.robots = List.copyOf(robots);
        this.keys = keys;
        this.maxConnections = maxConnections;
        this.handshakeMs = handshakeMs;
        this.writeMs = writeMs;
        this.resetEvery = resetEvery;
        this.watch = new ConnectionWatch(handshakeMs, writeMs);
    }

    int port() {
        return server.getLocalPort();
    }

    /** Starts the {@code accept-viewers} and {@code connection-watch} threads. */
    void accept() {
        watch.start();
        Thread t = new Thread(this::acceptLoop, "accept-viewers");
        t.setDaemon(true);
        t.start();
    }

    private void acceptLoop() {
        while (!server.isClosed()) {
            Socket s;
            try {
                s = server.getChannel().accept().socket();
            } catch (IOException e) {
                if (!server.isClosed()) {
                    LOG.warn("accept-viewers: accept failed: {}", e.getMessage());
                    LockSupport.parkNanos(100_000_000L); // back off: e.g. out of file descriptors
                }
                continue;
            }
            if (open.incrementAndGet() > maxConnections) {
                open.decrementAndGet();
                closeQuietly(s);
                long now = System.nanoTime();
                if (lastRefusalLog == 0 || now - lastRefusalLog >= TimeUnit.SECONDS.toNanos(1)) {
                    lastRefusalLog = now;
                    LOG.warn("viewer port: a connection closed at once: it holds at most {} at a time "
                            + "(--max-connections)", maxConnections);
                }
                continue;
            }
            ReplayViewer v = null;
            try {
                v = new ReplayViewer(s, ++serial, clock, robots, keys, resetEvery, new ConnectionClock(handshakeMs,
                        writeMs), watch, open::decrementAndGet);
                watch.watch(v);
                Thread t = new Thread(v, v.viewerName());
                t.setDaemon(true);
                t.start();
            } catch (RuntimeException | OutOfMemoryError e) { // out of threads
                if (v != null) {
                    watch.forget(v);
                }
                open.decrementAndGet();
                closeQuietly(s);
                if (!server.isClosed()) {
                    LOG.warn("accept-viewers: could not serve a connection: {}", e.toString());
                }
            }
        }
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // gone anyway
        }
    }

    @Override
    public void close() {
        try {
            server.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        watch.stopWhenIdle();
    }
}
