package robosim.protocol;

import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A client's deadline for the start of its connection: from the moment it is made until the server's stream
 * header has come (after TLS, when there is TLS) it may take at most so long, however the server trickles its
 * bytes, or the socket is closed under it (by the one {@code handshake-deadline} thread). What the client then
 * throws is replaced by a line saying that nothing answered in time ({@link #explain}). A port that answers
 * nothing ends here; every RoboSim port answers a client of another kind at once ({@link WrongClients}).
 */
final class HandshakeDeadline {
    /** The least a handshake is given, however short the connect timeout (a loaded machine still answers). */
    public static final long MIN_MS = 5_000;

    private static final ScheduledExecutorService TIMER = timer();

    private final long ms;
    private final ScheduledFuture<?> close;
    /** {@link #RUNNING}, then {@link #OVER} (in time) or {@link #PASSED} (the socket closed), whichever comes first. */
    private final AtomicInteger state = new AtomicInteger(RUNNING);
    private static final int RUNNING = 0;
    private static final int OVER = 1;
    private static final int PASSED = 2;

    private HandshakeDeadline(Socket socket, long ms) {
        this.ms = ms;
        this.close = TIMER.schedule(() -> {
            if (state.compareAndSet(RUNNING, PASSED)) {
                try {
                    socket.close();
                } catch (IOException ignored) {
                    // closing is all there was to do
                }
            }
        }, ms, TimeUnit.MILLISECONDS);
    }

    /** Starts the clock on {@code socket}: {@code ms}, at least {@link #MIN_MS}. */
    static HandshakeDeadline start(Socket socket, long ms) {
        return new HandshakeDeadline(socket, Math.max(MIN_MS, ms));
    }

    /** {@code e}, or, if the deadline closed the socket under it, the deadline's own line. */
    IOException explain(IOException e) {
        return over() ? e : passed();
    }

    /** The deadline's own line. */
    ProtocolException passed() {
        return new ProtocolException("no answer within " + (ms + 999) / 1000 + " s: nothing there speaks RoboSim's "
                + "object protocol");
    }

    /**
     * The handshake is over (in time, or failed on its own): the deadline no longer applies. False if the deadline
     * came first and closed the socket.
     */
    boolean over() {
        close.cancel(false);
        return state.compareAndSet(RUNNING, OVER) || state.get() == OVER;
    }

    private static ScheduledExecutorService timer() {
        ScheduledThreadPoolExecutor t = new ScheduledThreadPoolExecutor(1, r -> {
            Thread th = new Thread(r, "handshake-deadline");
            th.setDaemon(true);
            // (this JVM's one, whatever run first needed it: never holding a warm JVM's run's class loader)
            th.setContextClassLoader(HandshakeDeadline.class.getClassLoader());
            return th;
        });
        t.setRemoveOnCancelPolicy(true);
        return t;
    }
}
