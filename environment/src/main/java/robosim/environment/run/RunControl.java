package robosim.environment.run;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * Run control, as the loop applies it at the one point where a computed step's responses are about to
 * go out: pause (hold there), resume, step N (let N more out, then hold), and the pace
 * ({@code --speed}: simulated time at most that many times real time, counted afresh after every hold,
 * so a pause is never caught up in a rush). Loop thread only; the callers wait on futures.
 */
final class RunControl {
    private record StepWaiter(long target, CompletableFuture<Long> done) {
    }

    private final double speed;
    private final long stepMs;
    /** Publishes the run's state for the status; run before any caller is answered, so it sees the change. */
    private final Runnable publish;
    private boolean paused;
    private long budget;
    private boolean holding;
    private long paceOriginNanos;
    private long paceOriginStep;
    private final List<CompletableFuture<Void>> pauseWaiters = new ArrayList<>();
    private final List<StepWaiter> stepWaiters = new ArrayList<>();

    RunControl(double speed, long stepMs, Runnable publish) {
        this.speed = speed;
        this.stepMs = stepMs;
        this.publish = publish;
    }

    /** Before the start: nothing moves until {@link #resume} or {@link #stepN}. */
    void startPaused() {
        paused = true;
    }

    /** True while the run is to hold (at the release point, or before step 0). */
    boolean holdWanted() {
        return paused && budget == 0;
    }

    /** True while holding at the release point or before step 0. */
    boolean holding() {
        return holding;
    }

    /** What the status calls it: paused once the hold has taken effect, or no more steps are allowed. */
    boolean pausedNow() {
        return paused && (holding || budget == 0);
    }

    void pause(CompletableFuture<Void> held, boolean running) {
        paused = true;
        budget = 0;
        if (holding || !running) {
            publish.run();
            held.complete(null);
        } else {
            pauseWaiters.add(held);
        }
    }

    void resume(long released) {
        paused = false;
        budget = 0;
        settle(released, false);
    }

    void stepN(long n, CompletableFuture<Long> done, long released, boolean running) {
        paused = true;
        budget += n;
        if (!running) {
            publish.run();
            done.complete(released);
        } else {
            stepWaiters.add(new StepWaiter(released + n, done));
        }
    }

    /** The hold has taken effect (or the run waits before step 0): pause callers are answered. */
    void held(long released) {
        holding = true;
        publish.run();
        for (CompletableFuture<Void> w : pauseWaiters) {
            w.complete(null);
        }
        pauseWaiters.clear();
        settle(released, false);
    }

    /** A hold ends at {@code now}: the pace counts afresh from here. */
    void unheld(long now, long steps) {
        holding = false;
        restartPace(now, steps);
    }

    void restartPace(long now, long steps) {
        paceOriginNanos = now;
        paceOriginStep = steps;
    }

    /** When step {@code steps - 1}'s responses may go out at the earliest, by the pace (ns); 0: at once. */
    long paceDue(long steps) {
        if (speed <= 0) {
            return 0;
        }
        return paceOriginNanos + (long) ((steps - paceOriginStep) * stepMs * 1_000_000L / speed);
    }

    /** A step's responses are going out: a step N budget is used up by one. */
    void releasing() {
        if (paused && budget > 0) {
            budget--;
        }
    }

    /** Answers the step N callers whose steps are out; {@code over}: every caller is answered. */
    void settle(long released, boolean over) {
        publish.run();
        stepWaiters.removeIf(w -> {
            if (over || !paused || released >= w.target()) {
                w.done().complete(released);
                return true;
            }
            return false;
        });
        if (over) {
            pauseWaiters.forEach(w -> w.complete(null));
            pauseWaiters.clear();
        }
    }
}
