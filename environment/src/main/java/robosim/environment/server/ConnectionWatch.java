package robosim.environment.server;

import robosim.protocol.Printable;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The one mechanism that cuts off a connection that is late, whatever its kind (a robot, a shared
 * connection, a viewer, Geometry, a replay's viewer): a thread, {@code connection-watch}, looks a few times
 * per shortest limit at every open connection's {@link ConnectionClock} and closes each that has missed its
 * handshake deadline or not taken a write within the write timeout, with the reason; the connection's own
 * thread then fails with it and says goodbye as for any failure. Needed because a thread blocked in a
 * write (the loop's to a robot among them) cannot time itself. It closes sockets and nothing else.
 */
public final class ConnectionWatch {
    private static final Logger LOG = LoggerFactory.getLogger(ConnectionWatch.class);

    /** A watched connection. */
    public interface Watched {
        ConnectionClock clock();

        /** Closes the connection, so whatever its threads are blocked in fails. Any thread. */
        void drop();

        /** Its name for the log line. */
        String label();
    }

    private final Set<Watched> watched = ConcurrentHashMap.newKeySet();
    private final long periodMs;
    private volatile ScheduledExecutorService timer;
    /** Guarded by this: the owner is done, and the thread ends once nothing is left to watch. */
    private boolean idleEnds;
    /** Guarded by this: the thread has ended; a connection handed over now is dropped at once. */
    private boolean ended;

    /** Looks every quarter of the shortest limit given (ms; 0 or less: none), between 5 and 250 ms. */
    public ConnectionWatch(long... limitsMs) {
        long shortest = 1000;
        for (long ms : limitsMs) {
            if (ms > 0) {
                shortest = Math.min(shortest, ms);
            }
        }
        this.periodMs = Math.max(5, Math.min(250, shortest / 4));
    }

    /** Watches {@code w} from now until {@link #forget}; after the watch has ended, drops it at once. */
    public void watch(Watched w) {
        boolean refused;
        synchronized (this) {
            refused = ended;
            if (!refused) {
                watched.add(w);
            }
        }
        if (refused) {
            w.drop(); // (nobody would time it)
        }
    }

    public void forget(Watched w) {
        watched.remove(w);
    }

    /** Starts the {@code connection-watch} thread. */
    public void start() {
        timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "connection-watch");
            t.setDaemon(true);
            return t;
        });
        timer.scheduleWithFixedDelay(() -> check(System.nanoTime()), periodMs, periodMs, TimeUnit.MILLISECONDS);
    }

    /**
     * The owner is done: the thread ends once no connection is left to watch (those still open keep their clocks);
     * it looks at once, so that with none left it ends now rather than a period later (a warm JVM waits for a run's
     * threads to end before its next run).
     */
    public void stopWhenIdle() {
        ScheduledExecutorService t;
        synchronized (this) {
            idleEnds = true;
            t = ended ? null : timer;
        }
        if (t != null) {
            try {
                t.execute(() -> check(System.nanoTime()));
            } catch (java.util.concurrent.RejectedExecutionException over) {
                // it has ended meanwhile
            }
        }
    }

    /** One look at every clock: cuts off each connection that is late (one that fails to close does not stop the rest). */
    void check(long now) {
        for (Watched w : watched) {
            try {
                String why = w.clock().cutOffIfLate(now);
                if (why != null) {
                    watched.remove(w);
                    LOG.warn("{} cut off: {}", Printable.of(w.label(), 200), why);
                    w.drop();
                }
            } catch (RuntimeException e) {
                watched.remove(w);
                LOG.error("connection-watch: could not judge or close {}: {}", Printable.of(w.label(), 200), e.toString());
            }
        }
        synchronized (this) {
            if (idleEnds && watched.isEmpty()) {
                ended = true;
                timer.shutdown();
            }
        }
    }
}
