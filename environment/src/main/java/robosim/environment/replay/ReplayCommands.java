package robosim.environment.replay;

import robosim.environment.net.RunStatus;

import static robosim.environment.control.ControlReplies.ok;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import robosim.environment.control.ControlCommands;
import robosim.environment.control.ControlReplies;

/**
 * A replay's control requests, as the Control Panel and the browser page send them: {@code status},
 * {@code pause}, {@code resume} (or {@code start}), {@code step N}, {@code seek K}, {@code speed X}
 * ({@value ReplayClock#MIN_SPEED} to {@value ReplayClock#MAX_SPEED} times real time), {@code stop} (or
 * {@code shutdown}: the end goes to every viewer and the replay exits). Each is a question to the
 * {@link ReplayClock}, answered on its thread.
 */
public final class ReplayCommands implements ControlCommands {
    /** How long {@code step N} may take before it answers anyway, s (a recording viewer may hold it). */
    private static final long STEP_WAIT_S = 600;
    /** How long any other request waits for the clock, s. */
    private static final long WAIT_S = 10;

    private final ReplayClock clock;
    private final Path file;

    public ReplayCommands(ReplayClock clock, Path file) {
        this.clock = clock;
        this.file = file;
    }

    @Override
    public boolean waits(String verb) {
        return verb.equals("step");
    }

    @Override
    public String known() {
        return "status, pause, resume, step N, seek K, speed X, stop";
    }

    @Override
    public ObjectNode handle(String verb, String arg) throws Exception {
        return switch (verb) {
            case "status" -> status(answer(clock.status(), WAIT_S));
            case "pause" -> ok(answer(clock.pause(), WAIT_S));
            case "resume", "start" -> ok(answer(clock.resume(), WAIT_S));
            case "step" -> ok(answer(clock.step(arg.isEmpty() ? 1 : ControlReplies.positive("step", arg)), STEP_WAIT_S));
            case "seek" -> ok(answer(clock.seek(whole("seek", arg)), WAIT_S));
            case "speed" -> ok(answer(clock.speed(times(arg)), WAIT_S));
            case "stop", "shutdown" -> ok(answer(clock.stop("the replay was stopped from the control port"), WAIT_S));
            default -> null;
        };
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
