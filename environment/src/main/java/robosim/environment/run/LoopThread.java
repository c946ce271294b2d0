package robosim.environment.run;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.VirtualThreads;

/**
 * The thread the simulation loop runs on. A platform thread, {@code simulation-loop}; or, when every robot's control
 * code runs in this JVM on virtual threads and the JVM gives virtual threads one carrier
 * ({@code jdk.virtualThreadScheduler.parallelism=1}, which a one-JVM run sets unless told otherwise), a virtual thread
 * of that name: then a step passes from the loop to the control code and back on the one carrier, with no wake of
 * the operating system's ({@code docs/PERFORMANCE.md}, "Many short runs"). The system property
 * {@code robosim.loopThread} ({@code platform} or {@code virtual}) overrides the choice.
 *
 * <p>A virtual loop never waits for a time: a timed park of a virtual thread goes through the scheduler's timer, a
 * wake of the operating system's at every step that the hand-off has saved. It waits for its next event, and its
 * watch, a platform thread, hands it a wake ({@code tick}) at each of its ticks, when it judges its deadlines.
 *
 * <p>One carrier is not time-sliced: control code that computes without calling the robot keeps everything else off
 * it, the loop included, whose deadlines (the step timeout) would then never be judged. So a virtual loop is watched
 * by that platform thread, {@code loop-watch}: when the loop has not come round for {@link #STALL_MS}, it gives virtual
 * threads one more carrier ({@link VirtualThreads#widen}) and says so once; the loop then runs beside the code that
 * holds the first one and judges it as ever.
 */
public final class LoopThread {
    private static final Logger LOG = LoggerFactory.getLogger(LoopThread.class);
    /** The system property that chooses the loop's thread kind. */
    static final String PROPERTY = "robosim.loopThread";
    /** How long the loop may go without coming round before virtual threads get another carrier, ms. */
    static final long STALL_MS = 1_000;

    private LoopThread() {
    }

    /**
     * Whether the loop is to be virtual: when {@code robotsHere} (every robot's control code in this JVM) and this
     * JVM's virtual threads have one carrier, or as {@link #PROPERTY} says.
     */
    static boolean virtual(boolean robotsHere) {
        String asked = System.getProperty(PROPERTY, "");
        return VirtualThreads.available() && (asked.equals("virtual")
                || (!asked.equals("platform") && robotsHere && VirtualThreads.oneCarrier()));
    }

    /**
     * Starts {@code loop} on a {@code virtual} thread (with its watch) or a platform one; {@code round} is when the
     * loop last came round (System.nanoTime), {@code ended} counts down when it is done; a virtual loop is handed
     * {@code tick} every {@code tickNanos}.
     */
    static void start(Runnable loop, boolean virtual, LongSupplier round, CountDownLatch ended, long tickNanos,
            Runnable tick) {
        if (!virtual) {
            Thread t = new Thread(loop, "simulation-loop");
            t.setDaemon(true);
            t.start();
            return;
        }
        VirtualThreads.start("simulation-loop", loop);
        Thread watch = new Thread(() -> watch(round, ended, tickNanos, tick), "loop-watch");
        watch.setDaemon(true);
        watch.start();
    }

    /**
     * {@code loop-watch}: until the loop is done, hands it {@code tick} every {@code tickNanos}, and gives virtual
     * threads a carrier more when it stalls (once).
     */
    private static void watch(LongSupplier round, CountDownLatch ended, long tickNanos, Runnable tick) {
        long stall = TimeUnit.MILLISECONDS.toNanos(STALL_MS);
        boolean widened = false;
        try {
            while (!ended.await(tickNanos, TimeUnit.NANOSECONDS)) {
                tick.run();
                long idle = System.nanoTime() - round.getAsLong();
                if (idle > stall && !widened) {
                    widened = true;
                    int carriers = VirtualThreads.widen();
                    LOG.warn("the simulation loop has not come round for {} ms: code on its carrier thread computes "
                            + "without calling the robot (or the machine is very busy); {}", idle / 1_000_000,
                            carriers > 0 ? "virtual threads now have " + carriers + " carriers"
                                    : "their scheduler could not be given another carrier");
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
