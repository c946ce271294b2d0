package robosim.environment.replay;

import robosim.environment.run.RunStatus;

import static robosim.environment.control.ControlReplies.ok;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import robosim.environment.control.ControlCommands;
import robosim.environment.control.ControlReplies;
import robosim.environment.control.ControlVerb;

/**
 * A replay's control requests, as the Control Panel and the browser page send them, each declared once in
 * {@link #verbs} and each a question to the {@link ReplayClock}, answered on its thread: {@code speed} takes
 * {@value ReplayClock#MIN_SPEED} to {@value ReplayClock#MAX_SPEED} times real time; {@code stop} (or
 * {@code shutdown}) sends the end to every viewer and the replay exits.
 */
public final class ReplayCommands implements ControlCommands {
    /** How long {@code step N} may take before it answers anyway, s (a recording viewer may hold it). */
    private static final long STEP_WAIT_S = 600;
    /** How long any other request waits for the clock, s. */
    private static final long WAIT_S = 10;

    private final ReplayClock clock;
    private final Path file;
    private final List<ControlVerb> verbs;

    public ReplayCommands(ReplayClock clock, Path file) {
        this.clock = clock;
        this.file = file;
        this.verbs = List.of(
                ControlVerb.quick("status", "where the replay stands, its speed and viewers",
                        arg -> status(answer(clock.status(), WAIT_S))),
                ControlVerb.quick("pause", "holds the replay", arg -> ok(answer(clock.pause(), WAIT_S))),
                ControlVerb.quick("resume", "runs on", arg -> ok(answer(clock.resume(), WAIT_S))).alias("start"),
                ControlVerb.waiting("step N", "shows N more steps and holds", arg -> ok(answer(clock.step(arg.isEmpty()
                        ? 1 : ControlReplies.positive("step", arg)), STEP_WAIT_S))),
                ControlVerb.quick("seek K", "shows step K and goes on from there",
                        arg -> ok(answer(clock.seek(whole("seek", arg)), WAIT_S))),
                ControlVerb.quick("speed X", "X times real time", arg -> ok(answer(clock.speed(times(arg)), WAIT_S))),
                ControlVerb.quick("stop", "ends the replay (every viewer is told)", arg -> ok(answer(
                        clock.stop("the replay was stopped from the control port"), WAIT_S))).alias("shutdown"));
    }

    @Override
    public List<ControlVerb> verbs() {
        return verbs;
    }

    private ObjectNode status(ReplayStatus s) {
        ObjectNode n = ok(null);
        n.put("state", s.state().name());
        n.put("step", s.step());
        n.put("steps_per_s", s.state() == RunStatus.State.RUNNING ? Math.round(s.stepsPerSecond() * 10) / 10.0 : 0);
        n.put("file", String.valueOf(file));
        n.put("replay", true);
        n.put("first_step", s.firstStep());
        n.put("last_step", s.lastStep());
        n.put("speed", s.speed());
        n.put("at_end", s.atEnd());
        n.put("viewers", s.viewers());
        return n;
    }

    private static <T> T answer(CompletableFuture<T> f, long seconds) throws InterruptedException {
        try {
            return f.get(seconds, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            throw new IllegalArgumentException(e.getCause().getMessage());
        } catch (TimeoutException e) {
            throw new IllegalArgumentException("the replay did not answer within " + seconds + " s");
        }
    }

    private static long whole(String what, String arg) {
        try {
            return Long.parseLong(arg);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + " needs a step number, got \"" + ControlReplies.abbreviate(arg) + "\"");
        }
    }

    private static double times(String arg) {
        try {
            return Double.parseDouble(arg.startsWith("x") ? arg.substring(1) : arg);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("speed needs a factor from " + ReplayClock.MIN_SPEED + " to "
                    + ReplayClock.MAX_SPEED + ", got \"" + ControlReplies.abbreviate(arg) + "\"");
        }
    }
}
