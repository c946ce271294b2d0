package robosim.environment.run;

import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The one owner of simulation time, on its own thread, {@code simulation-loop}: the only code that advances the
 * step. Other threads hand it events through its {@link Inbox} ({@link #post}); it has each apply itself to the
 * {@link Run}, lets the run move on as far as it can, lets the transports' {@link LoopHook}s hand in what came
 * without an event and write what the run gave them, and between events keeps the run's deadlines (pace, step
 * timeout, Geometry timeout). It blocks on its inbox, timed to the next deadline, and in the run's own writes to
 * robots, which the connection watch cuts short past the write timeout; it holds no lock, ever. What it decides
 * lives in the {@link Run}; this class only drives it, as a test may by hand.
 */
public final class SimulationLoop implements Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(SimulationLoop.class);
    /** How long a thread posting an event waits for room in the loop's queue before giving up, ms. */
    private static final long POST_LIMIT_MS = 5_000;

    private final Inbox<Run> inbox;
    private final long tickNanos;
    private final CountDownLatch ended = new CountDownLatch(1);
    /** What else ends with the loop (the ports close), run last on the loop thread. */
    private final Runnable onEnd;
    /** The run it drives and the transports' hooks, from {@link #start} on (the loop thread's). */
    private Run run;
    private List<LoopHook> hooks;
    private long nextTick;
    /** When the loop last came round (System.nanoTime): what {@code loop-watch} watches. */
    private volatile long round = System.nanoTime();
    private final boolean robotsHere;
    /** The loop is a virtual thread: it waits for its next event, never for a time (its watch ticks it). Set before
     * it starts. */
    private boolean ticked;
    /** A tick's wake is in the inbox, not taken yet (one at a time, however long the loop takes). */
    private final java.util.concurrent.atomic.AtomicBoolean tickWaiting = new java.util.concurrent.atomic.AtomicBoolean();

    /**
     * {@code capacity}: events its inbox holds; {@code onEnd}: runs last, on the loop thread, once the run is
     * over. Events may be posted from now on; they are taken once it {@link #start}s.
     */
    public SimulationLoop(int capacity, Settings settings, Runnable onEnd) {
        this.inbox = new Inbox<>(capacity, POST_LIMIT_MS);
        this.tickNanos = tick(settings);
        this.onEnd = onEnd;
        this.robotsHere = settings.robotsInThisJvm() != null;
    }

    /** How often the loop's own deadlines are checked: a quarter of the shortest one, between 5 and 100 ms. */
    private static long tick(Settings s) {
        long shortest = Long.MAX_VALUE;
        for (long ms : new long[] {s.stepTimeoutMs(), s.geometryTimeoutMs()}) {
            if (ms > 0) {
                shortest = Math.min(shortest, ms);
            }
        }
        return TimeUnit.MILLISECONDS.toNanos(Math.max(5, Math.min(100, shortest / 4)));
    }

    /**
     * Starts the {@code simulation-loop} thread ({@link LoopThread}: a platform one, or a virtual one beside the
     * robots' control code), driving {@code driven}, with the transports' {@code loopHooks} (in-memory robots,
     * shared connections).
     */
    public void start(Run driven, List<LoopHook> loopHooks) {
        this.run = driven;
        this.hooks = List.copyOf(loopHooks);
        ticked = LoopThread.virtual(robotsHere); // (before the thread starts: it reads it)
        LoopThread.start(this, ticked, () -> round, ended, tickNanos, () -> {
            if (!tickWaiting.getAndSet(true)) {
                post(new LoopEvent.Wake());
            }
        });
        if (ticked) {
            LOG.info("the simulation loop runs on a virtual thread beside the control code");
        }
    }

    /**
     * Any thread: hands {@code event} to the loop; if the run is over (or the loop's queue stays full past the
     * post limit), the event is refused instead, so whoever waits on its answer is answered.
     */
    public void post(LoopEvent event) {
        if (!inbox.post(event) && !inbox.closed()) {
            LOG.warn("the simulation loop has not taken an event for {} ms; {} is refused", POST_LIMIT_MS,
                    event.getClass().getSimpleName());
        }
    }

    /** True once the loop is done: every later event is refused. */
    public boolean over() {
        return inbox.closed();
    }

    /** Blocks until the loop is done. */
    public void awaitEnd() throws InterruptedException {
        ended.await();
    }

    public boolean awaitEnd(long timeout, TimeUnit unit) throws InterruptedException {
        return ended.await(timeout, unit);
    }

    /** Before {@link #start}, or instead of it: the loop will never run; events are refused. */
    public void never() {
        inbox.close();
        ended.countDown();
    }

    @Override
    public void run() {
        try {
            settle(System.nanoTime());
            run.publish();
            while (!run.ended()) {
                long now = System.nanoTime();
                round = now;
                long due = run.paceDue();
                Inbox.Event<Run> e = pending() ? inbox.poll() : ticked && due == Long.MAX_VALUE ? inbox.take()
                        : inbox.poll(Math.max(0, Math.min(nextTick, due) - now));
                if (ticked) {
                    tickWaiting.set(false);
                }
                // everything queued by now is taken before any deadline is judged (a request or an answer
                // waiting in the queue is not late), and no more, so a busy queue never starves the deadlines
                for (int more = e == null ? 0 : inbox.size(); e != null; more--) {
                    e.apply(run);
                    settle(System.nanoTime());
                    e = more > 0 ? inbox.poll() : null;
                }
                while (run.answerHeldHellos()) { // (hellos held while a step was resolved)
                    settle(System.nanoTime());
                }
                now = System.nanoTime();
                if (now - nextTick >= 0) {
                    for (LoopHook hook : hooks) {
                        hook.handIn(run, true);
                    }
                    run.tick(now);
                    nextTick = now + tickNanos;
                }
                settle(now);
                run.publish();
            }
        } catch (InterruptedException e) {
            run.finish("the Environment was interrupted", false);
        } catch (RuntimeException | Error e) {
            LOG.error("the simulation loop failed", e);
            run.finish("the simulation loop failed: " + e, false);
        } finally {
            flush();
            run.closeOut();
            inbox.close();
            onEnd.run();
            ended.countDown();
        }
    }

    /**
     * After an event: the run moves on as far as it can, the hooks hand in what came without one (and the run
     * moves on again; what they give after that is applied at the next settle, the inbox looked at between),
     * then the hooks write what the run gave them.
     */
    private void settle(long now) {
        round = now;
        run.advance(now);
        boolean handed = false;
        for (int i = 0; i < hooks.size(); i++) {
            handed |= hooks.get(i).handIn(run, false);
        }
        if (handed) {
            run.advance(now);
        }
        flush();
    }

    private void flush() {
        for (int i = 0; i < hooks.size(); i++) {
            hooks.get(i).flush();
        }
    }

    private boolean pending() {
        for (int i = 0; i < hooks.size(); i++) {
            if (hooks.get(i).pending()) {
                return true;
            }
        }
        return false;
    }
}
