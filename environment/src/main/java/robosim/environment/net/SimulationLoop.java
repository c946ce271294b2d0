package robosim.environment.net;

import robosim.environment.server.ConnectionWatch;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The one owner of simulation time, on its own thread, {@code simulation-loop}: the only code that
 * advances the step. It takes events from its {@link Inbox}, has each apply itself to the {@link Run} and
 * lets the run move on as far as it can, and between events keeps the run's deadlines (pace, step timeout,
 * Geometry timeout). It blocks on its inbox, timed to the next deadline, and in the
 * run's own writes to robots, which the {@link ConnectionWatch} cuts short past the write timeout; it holds
 * no lock, ever. What it decides lives in the {@link Run}.
 */
final class SimulationLoop implements Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(SimulationLoop.class);

    private final ClientWorkerCoordinator coordinator;
    private final Inbox<Run> inbox;
    private final Run run;
    private final long tickNanos;
    private long nextTick;

    SimulationLoop(ClientWorkerCoordinator coordinator, Inbox<Run> inbox, Run run) {
        this.coordinator = coordinator;
        this.inbox = inbox;
        this.run = run;
        this.tickNanos = tick(coordinator.settings());
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

    @Override
    public void run() {
        try {
            run.advance(System.nanoTime());
            run.publish();
            while (!run.ended()) {
                long now = System.nanoTime();
                Inbox.Event<Run> e = inbox.poll(run.busy() ? 0 : Math.max(0, Math.min(nextTick, run.paceDue()) - now));
                // everything queued by now is taken before any deadline is judged (a request or an answer
                // waiting in the queue is not late), and no more, so a busy queue never starves the deadlines
                for (int more = e == null ? 0 : inbox.size(); e != null; more--) {
                    e.apply(run);
                    run.advance(System.nanoTime());
                    e = more > 0 ? inbox.poll() : null;
                }
                run.answerHeldHellos();
                now = System.nanoTime();
                if (now - nextTick >= 0) {
                    run.tick(now);
                    nextTick = now + tickNanos;
                }
                run.advance(now);
                run.publish();
            }
        } catch (InterruptedException e) {
            run.finish("the Environment was interrupted", false);
        } catch (RuntimeException | Error e) {
            LOG.error("the simulation loop failed", e);
            run.finish("the simulation loop failed: " + e, false);
        } finally {
            run.closeOut();
            coordinator.loopEnded();
        }
    }
}
