package robosim.protocol;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.channels.SocketChannel;

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

    /**
     * Connects, retrying while the port refuses (the server may not be up yet), until
     * {@code timeoutMs} has passed; returns null if it never accepted.
     */
    public static Socket connect(String host, int port, long timeoutMs) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
        while (true) {
            SocketChannel channel = SocketChannel.open();
            try {
                channel.connect(new InetSocketAddress(host, port));
                return channel.socket();
            } catch (ConnectException e) {
                channel.close();
                if (System.nanoTime() > deadline) {
                    return null;
                }
                Thread.sleep(RETRY_MS); // a retry interval: there is no event to wait on before the server exists
            }
        }
    }
}
