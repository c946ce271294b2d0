package robosim.environment.net;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The one deadline the simulation loop cannot keep itself: its own writes to robots ({@code THREADS},
 * {@code SEQUENTIAL}). A robot that stops reading would otherwise hold the loop in a socket write for
 * ever. This thread, {@code write-watchdog}, looks at every robot's write clock a few times per write
 * timeout and cuts off a robot that has not taken one write within it: its connection is closed, the
 * loop's write fails with the reason, and the loop removes the robot. It closes sockets and nothing
 * else; it never touches the run.
 */
final class WriteWatchdog {
    private static final Logger LOG = LoggerFactory.getLogger(WriteWatchdog.class);

    /** Something written to by the loop, with a clock on its current write. */
    interface Watched {
        /** How long its current write has taken so far, ns; 0 when none is under way. */
        long writingFor(long now);

        /** Closes its connection, so the write fails with {@code why}. */
        void cutOff(String why);

        String label();
    }

    private final List<Watched> watched = new CopyOnWriteArrayList<>();
    private final long limitNanos;
    private final long periodMs;
    private ScheduledExecutorService timer;

    WriteWatchdog(long limitMs) {
        this.limitNanos = TimeUnit.MILLISECONDS.toNanos(limitMs);
        this.periodMs = Math.max(5, Math.min(250, limitMs / 4)); // (limitMs <= 0: never started)
    }

    /** Times {@code w}'s writes from now on (unless there is no write timeout). */
    void watch(Watched w) {
        if (limitNanos > 0) {
            watched.add(w);
        }
    }

    void forget(Watched w) {
        watched.remove(w);
    }

    /** Starts the {@code write-watchdog} thread, if there is a write timeout. */
    void start() {
        if (limitNanos <= 0) {
            return;
        }
        timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "write-watchdog");
            t.setDaemon(true);
            return t;
        });
        timer.scheduleWithFixedDelay(() -> check(System.nanoTime()), periodMs, periodMs, TimeUnit.MILLISECONDS);
    }

    void stop() {
        if (timer != null) {
            timer.shutdownNow();
        }
    }

    /** One look at every clock: cuts off each write older than the limit. */
    void check(long now) {
        for (Watched w : watched) {
            if (w.writingFor(now) > limitNanos) {
                String why = "did not take a write within " + TimeUnit.NANOSECONDS.toMillis(limitNanos) + " ms";
                LOG.warn("{} cut off: {}", w.label(), why);
                watched.remove(w);
                w.cutOff(why);
            }
        }
    }
}
