package robosim.protocol;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;

/** Client-side connecting, shared by every process that connects to the Environment. */
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
            Socket s = new Socket();
            try {
                s.connect(new InetSocketAddress(host, port), (int) Math.max(1000, Math.min(timeoutMs, 10_000)));
                return s;
            } catch (ConnectException e) {
                s.close();
                if (System.nanoTime() > deadline) {
                    return null;
                }
                Thread.sleep(RETRY_MS); // a retry interval: there is no event to wait on before the server exists
            }
        }
    }
}
