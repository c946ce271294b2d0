package robosim.environment.net;

/**
 * The robots that were lost mid-run and stay in the world for their return ({@code --on-robot-loss HOLD}
 * or {@code WAIT}): since which step and when each is away, and which has a new connection that takes
 * over at the next step. A robot the world waits for ({@code WAIT}) is counted until it is back or
 * removed. Loop thread only.
 */
final class AwayRobots {
    private boolean[] away;
    private boolean[] returning;
    private boolean[] joining;
    private long[] sinceStep;
    private long[] sinceNanos;
    private boolean[] cameBack;
    private final boolean waitPolicy;
    private int awayCount;
    private int waitedFor;

    AwayRobots(int robots, RobotLoss policy) {
        this.away = new boolean[robots];
        this.returning = new boolean[robots];
        this.joining = new boolean[robots];
        this.cameBack = new boolean[robots];
        this.sinceStep = new long[robots];
        this.sinceNanos = new long[robots];
        this.waitPolicy = policy == RobotLoss.WAIT;
    }

    /** Robot i is away from step {@code step} on, lost at {@code now}. */
    void leave(int i, long step, long now) {
        if (!away[i]) {
            awayCount++;
        }
        away[i] = true; // (a new connection that said hello before the loss took effect still takes over)
        sinceStep[i] = step;
        sinceNanos[i] = now;
        if (waitPolicy) {
            waitedFor++;
        }
    }

    /** One more robot has joined: n robots. */
    void grow(int n) {
        away = java.util.Arrays.copyOf(away, n);
        returning = java.util.Arrays.copyOf(returning, n);
        joining = java.util.Arrays.copyOf(joining, n);
        sinceStep = java.util.Arrays.copyOf(sinceStep, n);
        sinceNanos = java.util.Arrays.copyOf(sinceNanos, n);
        cameBack = java.util.Arrays.copyOf(cameBack, n);
    }

    /** Robot i has just joined the world at {@code step}: it stands there until it takes part, at the next step. */
    void joining(int i, long step) {
        away[i] = true;
        returning[i] = true;
        joining[i] = true;
        sinceStep[i] = step;
        awayCount++;
    }

    /** True while robot i has joined and not yet taken part. */
    boolean isJoining(int i) {
        return joining[i];
    }

    /** Robot i has a new connection, which takes over at the next step. */
    void returning(int i) {
        returning[i] = true;
    }

    /** Robot i's new connection closed before it took over: it is away as before. */
    void notReturning(int i) {
        returning[i] = false;
    }

    /** Robot i takes part again, or is removed: it is no longer away. */
    void clear(int i) {
        if (away[i]) {
            awayCount--;
            if (waitPolicy && !joining[i]) {
                waitedFor--;
            }
        }
        away[i] = false;
        returning[i] = false;
        joining[i] = false;
    }

    boolean isAway(int i) {
        return away[i];
    }

    boolean isReturning(int i) {
        return returning[i];
    }

    /** Robot i is back, at {@code now}: its step timeout counts from then for the step it was given. */
    void back(int i, long now) {
        sinceNanos[i] = now;
        cameBack[i] = true;
    }

    /** False while robot i is away, or came back less than {@code limitNanos} ago (its step timeout runs from then). */
    boolean lateSinceBack(int i, long now, long limitNanos) {
        return !away[i] && (!cameBack[i] || now - sinceNanos[i] > limitNanos);
    }

    /** The first step robot i did not take part in. */
    long sinceStep(int i) {
        return sinceStep[i];
    }

    /** True if robot i is away, the world waits for it, and it has been away longer than {@code limitNanos}. */
    boolean waitedTooLong(int i, long now, long limitNanos) {
        return waitPolicy && away[i] && !returning[i] && !joining[i] && now - sinceNanos[i] > limitNanos;
    }

    /** True while a robot is away. */
    boolean any() {
        return awayCount > 0;
    }

    /** True while the world waits for a robot ({@code WAIT}) that has not come back. */
    boolean worldWaits() {
        return waitedFor > 0;
    }
}
