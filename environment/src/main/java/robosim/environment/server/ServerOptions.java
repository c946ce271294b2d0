package robosim.environment.server;

import java.net.InetAddress;
import java.net.UnknownHostException;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import robosim.protocol.Protocol;
import robosim.protocol.ResetOption;
import robosim.protocol.SimulationKeys;

/**
 * Where a server of viewers listens and how it treats connections: the address, the viewer and control ports,
 * the browser viewer's, the cap on connections, the handshake deadline and the write timeout (a picocli mixin of
 * environment.sh and replay.sh).
 */
public final class ServerOptions {
    @Option(names = "--bind", defaultValue = "127.0.0.1",
            description = "Address to listen on (default: ${DEFAULT-VALUE}, loopback only).")
    private String bind;

    @Option(names = "--viewer-port", defaultValue = "" + Protocol.DEFAULT_VIEWER_PORT,
            description = "Port for viewers (default: ${DEFAULT-VALUE}; 0 picks a free one).")
    private int viewerPort;

    @Option(names = "--control-port", defaultValue = "" + Protocol.DEFAULT_CONTROL_PORT,
            description = "The control port for the Control Panel (default: ${DEFAULT-VALUE}; 0 picks a free one; "
                    + "-1 none).")
    private int controlPort;

    @Mixin
    private WebPortOption web;

    @Option(names = "--max-connections", defaultValue = "" + ServerContext.DEFAULT_MAX_CONNECTIONS,
            description = "Connections each port holds at once beyond the robots the file names or lets join "
                    + "(<join max>); one more is closed at once (default: ${DEFAULT-VALUE}).")
    private int maxConnections;

    @Option(names = "--handshake-timeout-ms", defaultValue = "" + ServerContext.DEFAULT_HANDSHAKE_TIMEOUT_MS,
            description = "Drop a client whose hello (and proof) is not accepted within this time from its "
                    + "connection, however slowly it sends (default: ${DEFAULT-VALUE}).")
    private int handshakeTimeoutMs;

    @Option(names = "--write-timeout-ms", defaultValue = "" + ServerContext.DEFAULT_WRITE_TIMEOUT_MS,
            description = "Drop a client that does not take one write within this time, so none that stops reading "
                    + "holds the others (default: ${DEFAULT-VALUE}; 0 = never).")
    private long writeTimeoutMs;

    @Mixin
    private ResetOption reset;

    /** The address to listen on. */
    public InetAddress bind() throws UnknownHostException {
        return InetAddress.getByName(bind);
    }

    /** As given, for a line that names it. */
    public String bindName() {
        return bind;
    }

    public int viewerPort() {
        return viewerPort;
    }

    public int controlPort() {
        return controlPort;
    }

    public int webPort() {
        return web.port();
    }

    public int maxConnections() {
        return maxConnections;
    }

    public int handshakeTimeoutMs() {
        return handshakeTimeoutMs;
    }

    public long writeTimeoutMs() {
        return writeTimeoutMs;
    }

    public int resetEvery() {
        return reset.messages();
    }

    /** The context every connection of these ports is served with. */
    public ServerContext context(SimulationKeys keys, PortGuide guide) {
        return ServerContext.of(keys, resetEvery(), handshakeTimeoutMs, writeTimeoutMs, guide);
    }

    /**
     * What is wrong with these options, with {@code keys} (null: none) and listening on {@code address}, or null: a
     * value out of range, the browser viewer with a secret but no key pair, or ports beyond this machine without TLS
     * or without a handshake deadline.
     */
    public String problem(SimulationKeys keys, InetAddress address) {
        if (viewerPort < 0 || viewerPort > 65535) {
            return "--viewer-port must be from 0 to 65535, got " + viewerPort;
        }
        if (controlPort < -1 || controlPort > 65535) {
            return "--control-port must be from 0 to 65535 (-1: none), got " + controlPort;
        }
        if (maxConnections < 1) {
            return "--max-connections must be >= 1, got " + maxConnections;
        }
        if (handshakeTimeoutMs < 0 || writeTimeoutMs < 0 || resetEvery() < 0) {
            return "--handshake-timeout-ms, --write-timeout-ms and --reset-every must be >= 0";
        }
        String webProblem = web.problem(keys);
        if (webProblem != null) {
            return webProblem;
        }
        if (!address.isLoopbackAddress() && handshakeTimeoutMs == 0) {
            return "--bind " + bind + " needs a handshake deadline: --handshake-timeout-ms 0 would let a stranger hold "
                    + "a connection for ever";
        }
        if (!address.isLoopbackAddress() && (keys == null || keys.tls() == null)) {
            return "--bind " + bind + " opens every port beyond this machine: set ROBOSIM_KEYS to a directory made by "
                    + "scripts/make-keys.sh (TLS and the shared secret) for every process";
        }
        return null;
    }
}
