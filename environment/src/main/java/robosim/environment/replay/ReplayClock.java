package robosim.environment.replay;

import java.io.IOException;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.net.ViewerSink;
import robosim.environment.net.Viewers;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.WorldSnapshot;

/**
 * The one owner of a replay's time, thread {@code replay-clock}: where the replay stands in the recording,
 * whether it runs, how fast, and what each viewer is handed. Everything else asks it through its inbox (a
 * viewer's join, a control request, a viewer's room) and it answers on its own thread, so nothing else
 * ever touches the position. Like the Environment's loop it publishes to each viewer's coalescing
 * {@link robosim.environment.net.ViewerQueue} and never waits on one; a recording viewer that is a whole
 * backlog behind holds the next step until it has room.
 */
public final class ReplayClock {
    private static final Logger LOG = LoggerFactory.getLogger(ReplayClock.class);
    public static final double MIN_SPEED = 0.1;
    public static final double MAX_SPEED = 100;
    /** Requests waiting for the clock at most; one more is refused as busy. */
    static final int INBOX = 1024;
    /** The clock looks at stuck viewers at least this often, ns. */
    private static final long TICK_NANOS = 100_000_000L;

    /** What the replay is doing. */
    public enum State { WAITING, RUNNING, PAUSED, ENDED }

    /** Where the replay stands: {@code step} is the step shown (the snapshot's, -1, before the first). */
    public record Status(State state, long step, long firstStep, long lastStep, int steps, double speed,
            int viewers, boolean atEnd, double stepsPerSecond) {
    }

    private final RecordingReader recording;
    private final Viewers viewers;
    private final boolean exitAtEnd;
    private final boolean startPaused;
    private final BlockingQueue<Runnable> inbox = new ArrayBlockingQueue<>(INBOX);
    private final CountDownLatch ended = new CountDownLatch(1);
    private final Thread thread;
    // ---- the clock thread's own ----
    private State state = State.WAITING;
    private int steps;
    private int index = -1;
    private PoseUpdate shown;
    private double speed;
    private long intervalNanos;
    private long nextDue;
    private long stepsLeft;
    private CompletableFuture<String> stepping;
    private volatile long endedAt = -1;

    /**
     * @param exitAtEnd at the last step, send the end to every viewer and end (as the live run did); if
     *     false, hold there so viewers can seek back, until stopped
     * @param startPaused hold before the first step until resumed; if false, start when the first viewer joins
     */
    public ReplayClock(RecordingReader recording, Viewers viewers, double speed, boolean exitAtEnd, boolean startPaused) {
        this.recording = recording;
        this.viewers = viewers;
        this.exitAtEnd = exitAtEnd;
        this.startPaused = startPaused;
        this.steps = recording.steps();
        setSpeed(speed);
        this.thread = new Thread(this::run, "replay-clock");
        thread.setDaemon(true);
    }

    public void start() {
        thread.start();
    }

    /** Waits up to {@code ms} for the replay to end (stopped, or past its last step with exit at end). */
    public boolean awaitEnd(long ms) throws InterruptedException {
        return ended.await(ms, TimeUnit.MILLISECONDS);
    }

    /** The step shown when the replay ended (after {@link #awaitEnd}). */
    public long endedAt() {
        return endedAt;
    }

    // ---- asked from other threads ----------------------------------------------------------------------

    /** A viewer has said hello: it is added, and gets the world as the replay shows it now. */
    public CompletableFuture<WorldSnapshot> join(ViewerSink viewer) {
        return ask(now -> {
            viewers.add(viewer);
            WorldSnapshot at = snapshotNow();
            if (state == State.ENDED) {
                viewer.queue().end(new SimulationEnd(step(), "the replay has ended"));
            } else {
                viewer.queue().state(runState());
                if (state == State.WAITING && !startPaused) {
                    run(now);
                    LOG.info("replaying from step {} at x{}", step() + 1, speed);
                }
            }
            return at;
        });
    }

    /** A viewer's worker has ended (any thread). */
    public void left(ViewerSink viewer, String why) {
        viewers.remove(viewer, why);
    }

    /** A viewer's queue has room again: the clock looks at once. */
    public void roomFreed() {
        inbox.offer(() -> { });
    }

    public CompletableFuture<Status> status() {
        return ask(now -> new Status(state, step(), firstStep(), lastStep(), steps, speed, viewers.count(), atEnd(),
                1e9 / intervalNanos));
    }

    public CompletableFuture<String> pause() {
        return ask(now -> {
            live();
            if (state != State.PAUSED) {
                hold();
            }
            return "paused at step " + step();
        });
    }

    public CompletableFuture<String> resume() {
        return ask(now -> {
            live();
            if (atEnd()) {
                throw new IllegalStateException("at the end of the recording (step " + step() + "): seek first");
            }
            if (state != State.RUNNING) {
                run(now);
            }
            return "running from step " + step() + " at x" + speed;
        });
    }

    /** Shows the next {@code n} steps as fast as the viewers take them, then holds; answers once they are shown. */
    public CompletableFuture<String> step(long n) {
        return ask(now -> {
            live();
            if (stepping != null) {
                throw new IllegalStateException("a step is under way");
            }
            if (state != State.PAUSED) {
                hold();
            }
            stepping = new CompletableFuture<>();
            stepsLeft = n;
            if (atEnd()) {
                finishStepping();
            }
            return stepping;
        }).thenCompose(f -> f);
    }

    /** Shows recorded step {@code k} (the last recorded at or before it) at once, and goes on from there. */
    public CompletableFuture<String> seek(long k) {
        return ask(now -> {
            live();
            if (steps == 0 || k < firstStep() || k > lastStep()) {
                throw new IllegalArgumentException("step " + k + " is not in the recording ("
                        + (steps == 0 ? "it has no steps" : "steps " + firstStep() + " to " + lastStep()) + ")");
            }
            int lo = 0;
            int hi = steps - 1;
            while (lo < hi) { // the last index whose step is <= k
                int mid = (lo + hi + 1) >>> 1;
                if (recording.stepNumber(mid) <= k) {
                    lo = mid;
                } else {
                    hi = mid - 1;
                }
            }
            finishStepping();
            show(lo);
            nextDue = now + intervalNanos;
            return "at step " + step();
        });
    }

    public CompletableFuture<String> speed(double timesRealTime) {
        return ask(now -> {
            live();
            setSpeed(timesRealTime);
            nextDue = now + intervalNanos;
            return "speed x" + speed;
        });
    }

    /** Sends every viewer the end and ends the replay. */
    public CompletableFuture<String> stop(String why) {
        return ask(now -> {
            if (state != State.ENDED) {
                end(new SimulationEnd(step(), why));
            }
            return "stopped at step " + step();
        });
    }

    private <T> CompletableFuture<T> ask(LongFunction<T> action) {
        CompletableFuture<T> answer = new CompletableFuture<>();
        Runnable r = () -> {
            try {
                answer.complete(action.apply(System.nanoTime()));
            } catch (RuntimeException e) {
                answer.completeExceptionally(e);
            }
        };
        if (!inbox.offer(r)) {
            answer.completeExceptionally(new IllegalStateException("the replay is busy; try again"));
        } else if (ended.getCount() == 0 && inbox.remove(r)) { // (the clock has gone: nobody would answer)
            answer.completeExceptionally(new IllegalStateException("the replay has ended"));
        }
        return answer;
    }

    // ---- the clock thread ------------------------------------------------------------------------------

    private void run() {
        try {
            while (state != State.ENDED) {
                Runnable r = inbox.poll(waitNanos(System.nanoTime()), TimeUnit.NANOSECONDS);
                if (r != null) {
                    r.run();
                }
                long now = System.nanoTime();
                viewers.dropStuck(now);
                advance(now);
            }
        } catch (InterruptedException e) {
            end(new SimulationEnd(step(), "the replay was interrupted"));
        } finally {
            ended.countDown();
            for (Runnable r; (r = inbox.poll()) != null; ) {
                r.run(); // (each answers "the replay has ended" or what it did last)
            }
        }
    }

    private long waitNanos(long now) {
        boolean due = stepsLeft > 0 || state == State.RUNNING;
        if (!due || !viewers.haveRoom()) {
            return TICK_NANOS; // (a viewer with room again wakes the clock at once)
        }
        return stepsLeft > 0 ? 0 : Math.max(0, Math.min(nextDue - now, TICK_NANOS));
    }

    /** Shows the next step if one is due and every recording viewer has room. */
    private void advance(long now) {
        boolean stepNow = stepsLeft > 0;
        if (!stepNow && !(state == State.RUNNING && now - nextDue >= 0) || !viewers.haveRoom()) {
            return;
        }
        if (atEnd()) {
            reachedEnd();
            return;
        }
        show(index + 1);
        if (exitAtEnd && atEnd()) {
            reachedEnd(); // (the end follows the last step at once, as in the live run)
            return;
        }
        if (stepNow) {
            if (--stepsLeft == 0) {
                finishStepping();
            }
        } else {
            nextDue += intervalNanos;
            if (now - nextDue > intervalNanos) {
                nextDue = now; // behind (a viewer held it): no rush to catch up
            }
        }
    }

    private void show(int i) {
        try {
            shown = recording.step(i).update();
            index = i;
            viewers.publish(shown);
        } catch (IOException e) {
            LOG.error("the recording cannot be read on: {}", e.getMessage());
            steps = i; // (the replay ends before the damaged step)
        }
    }

    private void reachedEnd() {
        finishStepping();
        if (exitAtEnd) {
            SimulationEnd recorded = recording.end();
            end(recorded != null && steps == recording.steps() ? recorded : new SimulationEnd(step(),
                    "the recording stops at step " + step() + (recording.cutShort() == null ? "" : ": " + recording.cutShort())));
        } else if (state != State.PAUSED) {
            hold();
            LOG.info("at the end of the recording (step {}): seek, or stop", step());
        }
    }

    private void finishStepping() {
        stepsLeft = 0;
        if (stepping != null) {
            stepping.complete(atEnd() ? "at the end of the recording (step " + step() + ")" : "paused at step " + step());
            stepping = null;
        }
    }

    private void end(SimulationEnd end) {
        finishStepping();
        state = State.ENDED;
        endedAt = step();
        viewers.end(end);
        LOG.info("replay ended at step {}: {}", step(), end.reason());
    }

    private void run(long now) {
        state = State.RUNNING;
        nextDue = now;
        viewers.announce(runState());
    }

    private void hold() {
        state = State.PAUSED;
        viewers.announce(runState());
    }

    private void live() {
        if (state == State.ENDED) {
            throw new IllegalStateException("the replay has ended");
        }
    }

    private void setSpeed(double timesRealTime) {
        if (!(timesRealTime >= MIN_SPEED && timesRealTime <= MAX_SPEED)) {
            throw new IllegalArgumentException("speed must be from " + MIN_SPEED + " to " + MAX_SPEED + " (times real "
                    + "time), got " + timesRealTime);
        }
        speed = timesRealTime;
        long stepMs = recording.snapshot().timeStepMs() > 0 ? recording.snapshot().timeStepMs() : 100;
        intervalNanos = Math.max(1, Math.round(stepMs * 1e6 / speed));
    }

    private boolean atEnd() {
        return index >= steps - 1;
    }

    private long step() {
        return index < 0 ? recording.snapshot().step() : recording.stepNumber(index);
    }

    private long firstStep() {
        return steps == 0 ? -1 : recording.stepNumber(0);
    }

    private long lastStep() {
        return steps == 0 ? -1 : recording.stepNumber(steps - 1);
    }

    /** What the viewers are told the replay is doing: steps shown so far, as the live run's released steps. */
    private RunState runState() {
        RunState.Phase phase = switch (state) {
            case RUNNING -> RunState.Phase.RUNNING;
            case PAUSED -> RunState.Phase.PAUSED;
            default -> RunState.Phase.WAITING;
        };
        return new RunState(step() + 1, phase);
    }

    private WorldSnapshot snapshotNow() {
        WorldSnapshot s = recording.snapshot();
        return shown == null ? s : new WorldSnapshot(s.timeStepMs(), s.arena(), s.obstacles(), s.robotNames(),
                s.robots(), shown);
    }
}
