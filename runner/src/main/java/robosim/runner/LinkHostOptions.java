package robosim.runner;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import org.slf4j.Logger;
import picocli.CommandLine.Option;
import robosim.protocol.link.FirstHello;

/**
 * A link host's port and patience, the options of the learning host and the simulation host (a picocli mixin), and
 * its one peer awaited on that port: the first connection whose hello carries the host's key, several hellos read
 * at once ({@link FirstHello}), the refusals logged (at most {@link #MAX_LOGGED_REFUSALS}).
 */
public final class LinkHostOptions {
    /** Refused hellos logged, at most (strangers on this machine may try many). */
    static final int MAX_LOGGED_REFUSALS = 8;
    /** Connections whose hellos are awaited at once (strangers beyond are closed at once). */
    static final int MAX_PENDING = 16;

    @Option(names = "--port", defaultValue = "0", description = "The link's port on loopback (default: "
            + "${DEFAULT-VALUE}: one the system picks, printed).")
    int port;

    @Option(names = "--accept-timeout-s", defaultValue = "60", description = "Exit 3 if no peer has said hello with "
            + "the key within this long; hellos refused meanwhile (another key, another link) are logged (default: "
            + "${DEFAULT-VALUE}).")
    int acceptTimeoutS;

    /** What is wrong with the options, or null. */
    public String problem() {
        if (port < 0 || port > 65535) {
            return "--port must be 0 to 65535, got " + port;
        }
        return acceptTimeoutS < 1 ? "--accept-timeout-s must be >= 1, got " + acceptTimeoutS : null;
    }

    /** The host's port, bound on loopback (the caller closes it). */
    public ServerSocket listen() throws IOException {
        ServerSocket server = new ServerSocket();
        try {
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), MAX_PENDING);
        } catch (IOException e) {
            server.close();
            throw e;
        }
        return server;
    }

    /** How long the host waits for its peer, s. */
    public int acceptTimeoutS() {
        return acceptTimeoutS;
    }

    /**
     * The peer: the first connection to {@code server} that {@code handshake} welcomes (its hello checked against
     * {@code ROBOSIM_LINK_KEY}, when that is set, by the handshake) within {@code --accept-timeout-s}, or null; each
     * refusal logged to {@code log}.
     */
    public <T> FirstHello.Welcomed<T> awaitPeer(ServerSocket server, FirstHello.Handshake<T> handshake, Logger log)
            throws IOException {
        int[] refused = {0};
        return FirstHello.await(server, acceptTimeoutS * 1000L, MAX_PENDING, handshake, why -> {
            synchronized (refused) { // (refusals come from the hellos' threads)
                if (++refused[0] <= MAX_LOGGED_REFUSALS) {
                    log.warn("{}{}", why, refused[0] == MAX_LOGGED_REFUSALS ? " (further refusals are not logged)" : "");
                }
            }
        });
    }
}
