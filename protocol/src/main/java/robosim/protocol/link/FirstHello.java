package robosim.protocol.link;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import robosim.protocol.ProtocolException;

/**
 * A host's one peer (a learner, a tester): the first connection to its loopback port whose hello the link accepts.
 * Hellos are read several at once, each on a thread of its own ({@code link-hello[n]}) within the link's hello
 * deadline, so strangers that connect and say nothing do not keep the peer waiting; at most {@code maxPending} wait
 * at a time (one more is closed at once); each refusal is said to {@code refusals}.
 */
public final class FirstHello {
    private FirstHello() {
    }

    /** Reads a connection's hello and answers it: the served link, or a {@link ProtocolException} (a refusal). */
    public interface Handshake<T> {
        T welcome(Socket socket) throws IOException;
    }

    /**
     * The first connection to {@code server} that {@code handshake} welcomes within {@code timeoutMs}, or null; the
     * connections refused are closed, and any welcomed after the first.
     */
    public static <T> Welcomed<T> await(ServerSocket server, long timeoutMs, int maxPending, Handshake<T> handshake,
            Consumer<String> refusals) throws IOException {
        CompletableFuture<Welcomed<T>> first = new CompletableFuture<>();
        AtomicInteger pending = new AtomicInteger();
        long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
        int n = 0;
        while (!first.isDone()) {
            long left = (deadline - System.nanoTime()) / 1_000_000;
            if (left <= 0) {
                return first.getNow(null);
            }
            server.setSoTimeout((int) Math.min(200, left)); // (short: a welcome on another thread is seen soon)
            Socket socket;
            try {
                socket = server.accept();
            } catch (SocketTimeoutException e) {
                continue;
            }
            if (pending.incrementAndGet() > maxPending) {
                pending.decrementAndGet();
                refusals.accept("a connection from " + socket.getInetAddress().getHostAddress() + " closed: "
                        + maxPending + " hellos are awaited already");
                socket.close();
                continue;
            }
            Thread t = new Thread(() -> {
                try {
                    T link = handshake.welcome(socket);
                    if (!first.complete(new Welcomed<>(socket, link))) {
                        socket.close(); // (a second peer welcomed while the first was: the first keeps the host)
                    }
                } catch (ProtocolException e) {
                    refusals.accept("a hello from " + socket.getInetAddress().getHostAddress() + " refused: "
                            + e.getMessage());
                    close(socket);
                } catch (IOException | RuntimeException e) {
                    close(socket);
                } finally {
                    pending.decrementAndGet();
                }
            }, "link-hello[" + ++n + "]");
            t.setDaemon(true);
            t.start();
        }
        return first.getNow(null);
    }

    private static void close(Socket socket) {
        try {
            socket.close();
        } catch (IOException e) {
            // (closed already)
        }
    }

    /** The welcomed peer's connection and its link. */
    public record Welcomed<T>(Socket socket, T link) {
    }
}
