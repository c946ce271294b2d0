package robosim.environment.server;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

/**
 * The clocks of one connection, from its arrival: the handshake deadline (its hello must be in, and accepted
 * or refused, within the handshake timeout of its arrival, however slowly its bytes trickle in) and the
 * clock on its current write (a peer that does not take one write within the write timeout is cut off).
 * The connection's threads start and stop the clocks; the {@link ConnectionWatch} reads them and cuts the
 * connection off, once, with the reason. Any thread.
 */
public final class ConnectionClock {
    private static final int HANDSHAKE = 0;
    private static final int OVER = 1;
    private static final int EXPIRED = 2;

    private final long arrivedNanos = System.nanoTime();
    private final long handshakeLimitNanos;
    private final long writeLimitNanos;
    /** The handshake: under way, over in time, or expired; whichever of the last two comes first wins. */
    private final AtomicInteger handshake = new AtomicInteger(HANDSHAKE);
    private volatile long writingSince;
    /** Why the watch cut the connection off; null while it has not. */
    private final AtomicReference<String> cutOff = new AtomicReference<>();

    /** Limits in ms; 0 or less: none. */
    public ConnectionClock(long handshakeLimitMs, long writeLimitMs) {
        this.handshakeLimitNanos = handshakeLimitMs <= 0 ? Long.MAX_VALUE : TimeUnit.MILLISECONDS.toNanos(handshakeLimitMs);
        this.writeLimitNanos = writeLimitMs <= 0 ? Long.MAX_VALUE : TimeUnit.MILLISECONDS.toNanos(writeLimitMs);
    }

    /**
     * The connection's thread: its handshake is over (the hello is in); its deadline no longer applies. False
     * if the watch cut the connection off first ({@link #cutOffReason} says why).
     */
    public boolean handshakeOver() {
        return handshake.compareAndSet(HANDSHAKE, OVER) || handshake.get() == OVER;
    }

    /** A write begins (the clock runs until {@link #written}). */
    public void writing() {
        writingSince = System.nanoTime() | 1; // (never 0: 0 is "not writing")
    }

    public void written() {
        writingSince = 0;
    }

    /**
     * The watch, at {@code now}: if the connection is late, marks it cut off (once) and returns why; else
     * null. A hello in time wins over a deadline judged at the same moment.
     */
    String cutOffIfLate(long now) {
        if (now - arrivedNanos > handshakeLimitNanos && handshake.compareAndSet(HANDSHAKE, EXPIRED)) {
            String why = "no hello within " + TimeUnit.NANOSECONDS.toMillis(handshakeLimitNanos) + " ms";
            return cutOff.compareAndSet(null, why) ? why : null;
        }
        long since = writingSince;
        if (since != 0 && now - since > writeLimitNanos) {
            String why = "did not take a write within " + TimeUnit.NANOSECONDS.toMillis(writeLimitNanos) + " ms";
            return cutOff.compareAndSet(null, why) ? why : null;
        }
        return null;
    }

    /** Why the watch cut the connection off, or null if it has not. */
    public String cutOffReason() {
        String why = cutOff.get();
        if (why == null && handshake.get() == EXPIRED) { // (expired a moment before the reason is stored)
            return "no hello within " + TimeUnit.NANOSECONDS.toMillis(handshakeLimitNanos) + " ms";
        }
        return why;
    }
}
