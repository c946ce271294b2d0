package robosim.environment.replay;

import robosim.environment.run.RunStatus;

import java.util.concurrent.CompletableFuture;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.server.ViewerHost;
import robosim.environment.server.ViewerSink;
import robosim.environment.server.Viewers;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepNumbers;
import robosim.protocol.WorldSnapshot;

/**
 * The one owner of a replay's time, thread {@code replay-clock}: where it stands, whether it runs, how fast,
 * what each viewer is handed. Others ask through its inbox (joins, control requests, a viewer's room); it
 * answers on its thread. Like the Environment's loop it publishes to each viewer's coalescing queue and never
 * waits on one; a recording viewer a whole backlog behind holds the next step until it has room.
 */
public final class ReplayClock implements ViewerHost {
    private static final Logger LOG = LoggerFactory.getLogger(ReplayClock.class);
    public static final double MIN_SPEED = 0.1;
    public static final double MAX_SPEED = 100;
    /** The clock looks at stuck viewers at least this often, ns. */
    private static final long TICK_NANOS = 100_000_000L;

    private final RecordingCursor at;
    private final Viewers viewers;
    private final boolean exitAtEnd;
    private final boolean startPaused;
    private final ClockInbox inbox = new ClockInbox();
    private final Thread thread;
    /** The recorded robots' names, world order: what a viewer may watch. */
    private final java.util.List<String> robots;
    // ---- the clock thread's own ----
    private RunStatus.State state;
    private double speed;
    private long intervalNanos;
    private long nextDue;
    private long stepsLeft;
    private CompletableFuture<String> stepping;
    private volatile long endedAt = -1;

    /** {@code exitAtEnd}: end after the last step (else hold there until stopped); {@code startPaused}: hold before the first. */
    public ReplayClock(RecordingReader recording, Viewers viewers, double speed, boolean exitAtEnd, boolean startPaused) {
        this.at = new RecordingCursor(recording);
        this.robots = java.util.List.copyOf(recording.snapshot().robotNames());
        this.viewers = viewers;
        this.exitAtEnd = exitAtEnd;
        this.startPaused = startPaused;
        this.state = startPaused ? RunStatus.State.PAUSED : RunStatus.State.WAITING; // (held before its first step)
        setSpeed(speed);
        this.thread = new Thread(this::run, "replay-clock");
        thread.setDaemon(true);
    }

    public void start() {
        thread.start();
    }

    /** Waits up to {@code ms} for the replay to end (stopped, or past its last step with exit at end). */
    public boolean awaitEnd(long ms) throws InterruptedException {
        return inbox.awaitClosed(ms);
    }

    /** The step shown when the replay ended, as displays number it ({@link StepNumbers}; after {@link #awaitEnd}). */
    public long endedAt() {
        return endedAt;
    }

    @Override
    public String world() {
        return "this recording";
    }

    @Override
    public int robot(String name) {
        return robots.indexOf(name);
    }

    /** A viewer has said hello: it is added, and gets the world as the replay shows it now. */
    @Override
    public CompletableFuture<WorldSnapshot> join(ViewerSink viewer) {
        return inbox.ask(now -> {
            viewers.add(viewer);
            WorldSnapshot world = at.snapshot();
            if (state == RunStatus.State.ENDED) {
                viewer.queue().end(new SimulationEnd(at.step(), "the replay has ended"));
            } else {
                viewer.queue().state(runState());
                if (state == RunStatus.State.WAITING && !startPaused) {
                    run(now);
                    LOG.info("replaying from step {} at x{}", at.shown(), speed);
                }
            }
            return world;
        });
    }

    /** A viewer's worker has ended (any thread). */
    @Override
    public void left(ViewerSink viewer, String why, boolean cutOff) {
        viewers.remove(viewer, why);
        inbox.ask(now -> { // (and again after a join of it still queued, if any)
            viewers.remove(viewer, why);
            return null;
        });
    }

    /** A viewer's queue has room again: the clock looks at once. */
    @Override
    public void roomFreed(ViewerSink viewer) {
        inbox.wake();
    }

    public CompletableFuture<ReplayStatus> status() {
        return inbox.ask(now -> new ReplayStatus(state, at.shown(), StepNumbers.shown(at.firstStep()),
                StepNumbers.shown(at.lastStep()), at.steps(), speed, viewers.count(), at.atEnd(),
                1e9 / intervalNanos));
    }

    public CompletableFuture<String> pause() {
        return inbox.ask(now -> {
            live();
            if (state != RunStatus.State.PAUSED) {
                hold();
            }
            return "paused at step " + at.shown();
        });
    }

    public CompletableFuture<String> resume() {
        return inbox.ask(now -> {
            live();
            if (at.atEnd()) {
                throw new IllegalStateException("at the end of the recording (step " + at.shown() + "): seek first");
            }
            if (state != RunStatus.State.RUNNING) {
                run(now);
            }
            return "running from step " + at.shown() + " at x" + speed;
        });
    }

    /** Shows the next {@code n} steps as fast as the viewers take them, then holds; answers once they are shown. */
    public CompletableFuture<String> step(long n) {
        return inbox.ask(now -> {
            live();
            if (stepping != null) {
                throw new IllegalStateException("a step is under way");
            }
            if (state != RunStatus.State.PAUSED) {
                hold();
            }
            stepping = new CompletableFuture<>();
            stepsLeft = n;
            if (at.atEnd()) {
                finishStepping();
            }
            return stepping;
        }).thenCompose(f -> f);
    }

    /**
     * Shows step {@code k} as displays number it ({@link StepNumbers}; the last recorded at or before it) at once,
     * and goes on from there. Every viewer gets the world at that step right before its update, so it starts its
     * picture afresh there (trails, its steps per second) instead of joining the steps across the jump.
     */
    public CompletableFuture<String> seek(long k) {
        return inbox.ask(now -> {
            live();
            int i = at.indexOf(k);
            finishStepping();
            show(i, true);
            nextDue = now + intervalNanos;
            return "at step " + at.shown();
        });
    }

    public CompletableFuture<String> speed(double timesRealTime) {
        return inbox.ask(now -> {
            live();
            setSpeed(timesRealTime);
            nextDue = now + intervalNanos;
            return "speed x" + speed;
        });
    }

    /** Sends every viewer the end and ends the replay. */
    public CompletableFuture<String> stop(String why) {
        return inbox.ask(now -> {
            if (state != RunStatus.State.ENDED) {
                end(new SimulationEnd(at.step(), why));
            }
            return "stopped at step " + at.shown();
        });
    }

    // ---- the clock thread ------------------------------------------------------------------------------

    private void run() {
        try {
            while (state != RunStatus.State.ENDED) {
                inbox.runNext(waitNanos(System.nanoTime()));
                advance(System.nanoTime());
            }
        } catch (InterruptedException | RuntimeException | Error e) {
            LOG.error("the replay stops: {}", e.toString());
            end(new SimulationEnd(at.step(), "the replay failed: " + e));
        } finally {
            inbox.close(); // (what is left answers "the replay has ended", or what it did last)
        }
    }

    private long waitNanos(long now) {
        boolean due = stepsLeft > 0 || state == RunStatus.State.RUNNING;
        if (!due || !viewers.haveRoom()) {
            return TICK_NANOS; // (a viewer with room again wakes the clock at once)
        }
        return stepsLeft > 0 ? 0 : Math.max(0, Math.min(nextDue - now, TICK_NANOS));
    }

    /** Shows the next step if one is due and every recording viewer has room. */
    private void advance(long now) {
        boolean stepNow = stepsLeft > 0;
        if (!stepNow && !(state == RunStatus.State.RUNNING && now - nextDue >= 0) || !viewers.haveRoom()) {
            return;
        }
        if (at.atEnd()) {
            reachedEnd();
            return;
        }
        show(at.index() + 1, false);
        if (exitAtEnd && at.atEnd()) {
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

    /** Shows the i-th recorded step; {@code sought}: a seek, whose update goes with the world at that step. */
    private void show(int i, boolean sought) {
        PoseUpdate u = at.show(i);
        if (u != null) {
            WorldSnapshot changed = at.takeWorldChange();
            viewers.publish(sought ? at.snapshot() : changed, sought ? u.withPiece(robosim.protocol.Traces.NONE) : u,
                    at::view); // (a seek's world holds the whole drawing: its update draws nothing more)
        }
    }

    private void reachedEnd() {
        finishStepping();
        if (exitAtEnd) {
            end(at.end());
        } else if (state != RunStatus.State.PAUSED) {
            hold();
            LOG.info("at the end of the recording (step {}): seek, or stop", at.shown());
        }
    }

    private void finishStepping() {
        stepsLeft = 0;
        if (stepping != null) {
            stepping.complete(at.atEnd() ? "at the end of the recording (step " + at.shown() + ")" : "paused at step " + at.shown());
            stepping = null;
        }
    }

    private void end(SimulationEnd end) {
        finishStepping();
        state = RunStatus.State.ENDED;
        endedAt = at.shown();
        viewers.end(end);
        LOG.info("replay ended at step {}: {}", at.shown(), end.reason());
    }

    private void run(long now) {
        state = RunStatus.State.RUNNING;
        nextDue = now;
        viewers.announce(runState());
    }

    private void hold() {
        state = RunStatus.State.PAUSED;
        viewers.announce(runState());
    }

    private void live() {
        if (state == RunStatus.State.ENDED) {
            throw new IllegalStateException("the replay has ended");
        }
    }

    private void setSpeed(double timesRealTime) {
        if (!(timesRealTime >= MIN_SPEED && timesRealTime <= MAX_SPEED)) {
            throw new IllegalArgumentException("speed must be from " + MIN_SPEED + " to " + MAX_SPEED + " (times real "
                    + "time), got " + timesRealTime);
        }
        speed = timesRealTime;
        intervalNanos = Math.max(1, Math.round(at.timeStepMs() * 1e6 / speed));
    }

    /** What the viewers are told the replay is doing: steps shown so far, as the live run's released steps. */
    private RunState runState() {
        RunState.Phase phase = switch (state) {
            case RUNNING -> RunState.Phase.RUNNING;
            case PAUSED -> RunState.Phase.PAUSED;
            default -> RunState.Phase.WAITING;
        };
        return new RunState(at.shown(), phase);
    }
}
