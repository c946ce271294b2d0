package robosim.environment.net;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * What the loop publishes about its run for other threads (the control port's status, the summary):
 * written by the loop thread only, read by anyone, never locked. Counts are as of the last step out.
 */
final class PublishedRun {
    private static final long RATE_WINDOW_NANOS = 500_000_000L;

    volatile RunStatus.State phase = RunStatus.State.WAITING;
    volatile long stepsReleased;
    volatile double recentRate;
    volatile long startNanos;
    volatile long endNanos;
    volatile String endReason = "";
    volatile boolean completed;
    volatile long messagesDelivered;
    volatile long messagesOutOfRange;
    volatile long messagesRefused;
    volatile int geometryLosses;
    volatile int geometryAttaches;
    volatile String geometry = "waiting";
    /** A robot that has said hello, and whether it takes part (waits for the start, or has not left). */
    record Member(String name, RobotPeer worker, boolean takesPart) {
        /** Its connection is open and it takes part; read when asked, so a connection closed after the end counts. */
        boolean connected() {
            return takesPart && !worker.closed();
        }
    }

    volatile List<Member> roster = List.of();
    /** Every robot in the world (the file's, then those that joined) and its state, in world order. */
    volatile List<RobotState> states = List.of();
    final List<Departure> departures = new CopyOnWriteArrayList<>();
    private long rateMarkNanos;
    private long rateMarkSteps;

    /** The run begins (step 0 goes out) at {@code now}. */
    void begin(long now) {
        startNanos = now;
        rateMarkNanos = now;
        rateMarkSteps = stepsReleased;
    }

    /** A step's responses went out at {@code now}; the rate is the steps per second over the last half second. */
    void released(long steps, long now) {
        stepsReleased = steps;
        if (now - rateMarkNanos >= RATE_WINDOW_NANOS) {
            recentRate = (steps - rateMarkSteps) * 1e9 / (now - rateMarkNanos);
            rateMarkNanos = now;
            rateMarkSteps = steps;
        }
    }

    /** A hold ended at {@code now}: the rate counts from here (the hold is not a slow step). */
    void resumed(long now) {
        rateMarkNanos = now;
        rateMarkSteps = stepsReleased;
    }

    void messages(long delivered, long outOfRange, long refused) {
        messagesDelivered = delivered;
        messagesOutOfRange = outOfRange;
        messagesRefused = refused;
    }

    /** The run's summary; its steps are those released (a step computed and held by the pace is not one yet). */
    RunSummary summary(int robots) {
        long start = startNanos;
        long end = endNanos;
        double wall = start == 0 ? 0 : ((end == 0 ? System.nanoTime() : end) - start) / 1e9;
        return new RunSummary(stepsReleased, robots, wall, endReason, completed, messagesDelivered,
                messagesOutOfRange, messagesRefused, departures.size(), geometryLosses, geometryAttaches,
                List.copyOf(departures));
    }

    /** What the control port reports now; {@code fileNames}: the file's robots, until the loop has published its own. */
    RunStatus status(List<String> fileNames, int viewers) {
        RunStatus.State state = phase;
        List<String> connected = new java.util.ArrayList<>();
        List<String> left = new java.util.ArrayList<>();
        for (Member m : roster) {
            if (m.connected()) {
                connected.add(m.name());
            } else if (state != RunStatus.State.WAITING) {
                left.add(m.name());
            }
        }
        List<RobotState> now = states;
        List<String> names = now.isEmpty() ? fileNames : now.stream().map(RobotState::name).toList();
        return new RunStatus(state, stepsReleased, state == RunStatus.State.RUNNING ? recentRate : 0, names,
                List.copyOf(connected), List.copyOf(left), geometry, endReason, viewers, now);
    }
}
