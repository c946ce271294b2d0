package robosim.environment.server;

import java.util.concurrent.atomic.AtomicLong;
import robosim.protocol.Limits;

/**
 * One budget for everything that clients not yet accepted hold in the Environment, across every connection
 * of every port: the bytes of their hellos (and proofs) read and not yet accepted or refused, and the
 * refusals not yet written to them. Each connection's {@link Handshake} takes from it before it reads a
 * message (the most a stranger's message may be, then gives back what the message did not use) and gives
 * everything back when the handshake ends. Past it a new connection is closed at once and a stranger that
 * wants more is dropped; accepted clients and the world go on. Sized so that every port's connection cap
 * full of the largest strangers fits a 256 MiB heap. Any thread.
 */
public final class StrangerBudget {
    /** The default: 16 MiB, a thousand strangers' largest hellos at once, or a few legitimate shared connections of thousands of robots. */
    static final long DEFAULT_BYTES = 16L << 20;

    private final long total;
    private final AtomicLong free;

    StrangerBudget(long bytes) {
        if (bytes < Limits.MAX_HELLO_BYTES) {
            throw new IllegalArgumentException("a stranger budget must hold one hello (" + Limits.MAX_HELLO_BYTES
                    + " bytes), got " + bytes);
        }
        this.total = bytes;
        this.free = new AtomicLong(bytes);
    }

    /**
     * Takes {@code bytes}; false (and nothing taken) if the budget does not have them. Only a connection's
     * {@code first} message may use the last {@link #HEADROOM} bytes: one stranger that sends much cannot keep
     * a robot, a viewer or Geometry from saying hello.
     */
    boolean take(long bytes, boolean first) {
        long keep = first ? 0 : HEADROOM;
        long f;
        do {
            f = free.get();
            if (f - keep < bytes) {
                return false;
            }
        } while (!free.compareAndSet(f, f - bytes));
        return true;
    }

    /** Kept for connections' first messages (hellos): 64 of the largest at once. */
    static final long HEADROOM = 64L * Limits.MAX_HELLO_BYTES;

    void give(long bytes) {
        free.addAndGet(bytes);
    }

    /** True while not even one more stranger's hello fits: a new connection is closed at once. */
    boolean full() {
        return free.get() < Limits.MAX_HELLO_BYTES;
    }

    long total() {
        return total;
    }
}
