package robosim.environment.replay;

/**
 * Where a replay stands, as its {@code status} request tells: {@code step} is the step shown (the
 * snapshot's, -1, before the first), {@code stepsPerSecond} the pace its speed sets.
 */
public record ReplayStatus(State state, long step, long firstStep, long lastStep, int steps, double speed,
        int viewers, boolean atEnd, double stepsPerSecond) {
    /** What the replay is doing. */
    public enum State { WAITING, RUNNING, PAUSED, ENDED }
}
