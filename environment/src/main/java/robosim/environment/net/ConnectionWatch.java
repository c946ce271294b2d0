package robosim.environment.net;

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
    private ScheduledExecutorService timer;
    private volatile boolean idleEnds;

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

    /** Watches {@code w} from now until {@link #forget}. */
    public void watch(Watched w) {
        watched.add(w);
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

    public void stop() {
        if (timer != null) {
            timer.shutdownNow();
        }
    }

    /** The owner is done: the thread ends once no connection is left to watch (those still open keep their clocks). */
    public void stopWhenIdle() {
        idleEnds = true;
    }

    /** One look at every clock: cuts off each connection that is late. */
    void check(long now) {
        for (Watched w : watched) {
            String why = w.clock().cutOffIfLate(now);
            if (why != null) {
                watched.remove(w);
                LOG.warn("{} cut off: {}", Printable.of(w.label(), 200), why);
                w.drop();
            }
        }
        if (idleEnds && watched.isEmpty()) {
            timer.shutdown();
        }
    }
}
