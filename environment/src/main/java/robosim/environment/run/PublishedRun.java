package robosim.environment.run;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;

/**
 * What the loop publishes about its run for other threads (the control port's status and queries, the summary,
 * whoever waits for the start): written on the loop thread only (the robots and the phase by the
 * {@link StatusBoard}, from the run's parts; what was released, the counts and the outcome by the {@link Run} as
 * they happen), read by anyone, never locked. What the run has released is one {@link ReleasedWorld}; counts are as
 * of the last step out.
 */
public final class PublishedRun {
    private static final long RATE_WINDOW_NANOS = 500_000_000L;

    /** A robot that has said hello, and whether it takes part (waits for the start, or has not left). */
    record Member(String name, RobotPeer peer, boolean takesPart) {
        /** Its connection is open and it takes part; read when asked, so a connection closed after the end counts. */
        boolean connected() {
            return takesPart && !peer.closed();
        }
    }

    private final LongSupplier clock;
    private final CountDownLatch ready = new CountDownLatch(1);
    private volatile boolean began;

    private volatile RunStatus.State phase = RunStatus.State.WAITING;
    /** The world as last released (from step 0 on), or null before. */
    private volatile ReleasedWorld world;
    private volatile double recentRate;
    private volatile long startNanos;
    private volatile long endNanos;
    private volatile String endReason = "";
    private volatile boolean completed;
    private volatile boolean experimentFailed;
    private volatile long messagesDelivered;
    private volatile long messagesOutOfRange;
    private volatile long messagesRefused;
    private volatile int geometryLosses;
    private volatile int geometryAttaches;
    private volatile String geometry = "waiting";
    private volatile List<Member> roster = List.of();
    /** Every robot in the world (the file's, then those that joined) and its state, in world order. */
    private volatile List<RobotState> states = List.of();
    /** Robots that left mid-run, in the order they did. */
    private volatile List<Departure> departures = List.of();
    private long rateMarkNanos;
    private long rateMarkSteps;

    /** {@code clock}: the run's (ns), for the wall time of a run under way. */
    PublishedRun(LongSupplier clock) {
        this.clock = clock;
    }

    /** The run's built-in metrics as of the last step out, by name (none before the run began). */
    public Map<String, Double> metrics() {
        ReleasedWorld w = world;
        return w == null ? Map.of() : w.metrics();
    }

    /** Steps whose responses have gone out. */
    public long stepsReleased() {
        ReleasedWorld w = world;
        return w == null ? 0 : w.steps();
    }

    /** The run begins (step 0 goes out) at {@code now}, from {@code start}, the world before step 0. */
    void begin(long now, ReleasedWorld start) {
        startNanos = now;
        rateMarkNanos = now;
        rateMarkSteps = stepsReleased();
        world = start;
    }

    /** The status's phase, and where geometry is resolved (the {@link StatusBoard}'s). */
    void phase(RunStatus.State now, String geometryWhere) {
        phase = now;
        geometry = geometryWhere;
    }

    /**
     * The robots that have said hello, every robot in the world and its state, and who has left (the
     * {@link StatusBoard}'s).
     */
    void robots(List<Member> members, List<RobotState> inWorld, List<Departure> left) {
        roster = List.copyOf(members);
        states = List.copyOf(inWorld);
        departures = List.copyOf(left);
    }

    /** Every robot in the world and its state, in world order, as last published. */
    public List<RobotState> states() {
        return states;
    }

    /** Geometry processes attached so far. */
    void geometryAttaches(int attaches) {
        geometryAttaches = attaches;
    }

    /** Geometry processes lost so far. */
    void geometryLosses(int losses) {
        geometryLosses = losses;
    }

    /** The run's outcome, {@code reason} and whether it {@code completed} its steps, on record before any robot hears of it. */
    void outcome(String reason, boolean completedSteps) {
        endReason = reason;
        completed = completedSteps;
    }

    /** The world's loop functions failed: the run ends with their line as its reason. */
    void experimentFailed() {
        experimentFailed = true;
    }

    /** The run ended at {@code nanos}: {@code reason}, and whether it {@code completed} its steps. */
    void ended(String reason, boolean completedSteps, long nanos) {
        outcome(reason, completedSteps);
        endNanos = nanos;
    }

    /** Why the run ended ("" before it has). */
    String endReason() {
        return endReason;
    }

    /**
     * Every client is there and the run has begun or holds before step 1 ({@code began}), or it ended first
     * (false): whoever waits for the start is answered, once.
     */
    public void ready(boolean hasBegun) {
        if (ready.getCount() > 0) {
            began = hasBegun;
            ready.countDown();
        }
    }

    /** Waits until every client is there and the run has begun (or holds before step 1): true, or false if it ended first or on timeout. */
    public boolean awaitReady(long timeout, TimeUnit unit) throws InterruptedException {
        return ready.await(timeout, unit) && began;
    }

    /** A step's responses went out at {@code now}: the world after it; the rate is the steps per second over the last half second. */
    void released(ReleasedWorld w, long now) {
        world = w;
        long steps = w.steps();
        if (now - rateMarkNanos >= RATE_WINDOW_NANOS) {
            recentRate = (steps - rateMarkSteps) * 1e9 / (now - rateMarkNanos);
            rateMarkNanos = now;
            rateMarkSteps = steps;
        }
    }

    /** A hold ended at {@code now}: the rate counts from here (the hold is not a slow step). */
    void resumed(long now) {
        rateMarkNanos = now;
        rateMarkSteps = stepsReleased();
    }

    void messages(long delivered, long outOfRange, long refused) {
        messagesDelivered = delivered;
        messagesOutOfRange = outOfRange;
        messagesRefused = refused;
    }

    /** The run's summary; its steps are those released (a step computed and held by the pace is not one yet). */
    public RunSummary summary(int robots) {
        long start = startNanos;
        long end = endNanos;
        double wall = start == 0 ? 0 : ((end == 0 ? clock.getAsLong() : end) - start) / 1e9;
        List<Departure> left = departures;
        return new RunSummary(stepsReleased(), robots, wall, endReason, completed, messagesDelivered,
                messagesOutOfRange, messagesRefused, left.size(), geometryLosses, geometryAttaches, left,
                experimentFailed);
    }

    /** What the control port reports now; {@code fileNames}: the file's robots, until the loop has published its own. */
    public RunStatus status(List<String> fileNames, int viewers) {
        RunStatus.State state = phase;
        List<String> connected = new ArrayList<>();
        List<String> left = new ArrayList<>();
        for (Member m : roster) {
            if (m.connected()) {
                connected.add(m.name());
            } else if (state != RunStatus.State.WAITING) {
                left.add(m.name());
            }
        }
        List<RobotState> now = states;
        List<String> names = now.isEmpty() ? fileNames : now.stream().map(RobotState::name).toList();
        return new RunStatus(state, stepsReleased(), state == RunStatus.State.RUNNING ? recentRate : 0, names,
                List.copyOf(connected), List.copyOf(left), geometry, endReason, viewers, now);
    }
}
