package robosim.protocol;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.UnknownHostException;
import java.nio.channels.SocketChannel;
import java.util.function.Consumer;

/**
 * Client-side connecting, shared by every process that connects to the Environment. Sockets come
 * from blocking {@link SocketChannel}s: on JDK 17 a blocking read on a channel's socket is one
 * system call, where a plain {@link Socket} polls first (read, poll, read); measured in
 * {@code environment/README.md}.
 */
public final class Connector {
    private static final long RETRY_MS = 50;

    private Connector() {
    }

    /** Null if {@code port} can be connected to, else what is wrong with it, for a one-line error. */
    public static String badPort(int port) {
        return port >= 1 && port <= 65535 ? null : "port " + port + " is not a TCP port (1..65535)";
    }

    /** As {@link #connect(String, int, long, Consumer)}, silently. */
    public static Socket connect(String host, int port, long timeoutMs) throws IOException, InterruptedException {
        return connect(host, port, timeoutMs, line -> { });
    }

    /**
     * Connects, retrying while the port refuses (the server may not be up yet), until
     * {@code timeoutMs} has passed; returns null if it never accepted. The first refusal tells
     * {@code waiting} one line, {@code connecting to HOST:PORT ...}, so a person knows what the
     * process waits for.
     *
     * @throws UnknownHostException naming the host, when it has no address
     */
    public static Socket connect(String host, int port, long timeoutMs, Consumer<String> waiting)
            throws IOException, InterruptedException {
        InetAddress address;
        try {
            address = InetAddress.getByName(host);
        } catch (UnknownHostException e) {
            throw new UnknownHostException("unknown host " + host);
        }
        long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
        boolean told = false;
        while (true) {
            SocketChannel channel = SocketChannel.open();
            try {
                channel.connect(new InetSocketAddress(address, port));
                return channel.socket();
            } catch (ConnectException e) {
                channel.close();
                if (System.nanoTime() > deadline) {
                    return null;
                }
                if (!told) {
                    told = true;
                    waiting.accept("connecting to " + host + ":" + port + " ... (for up to " + timeoutMs / 1000
                            + " s; is the Environment running?)");
                }
                Thread.sleep(RETRY_MS); // a retry interval: there is no event to wait on before the server exists
            } catch (IOException | RuntimeException e) {
                channel.close();
                throw e;
            }
        }
    }
}
