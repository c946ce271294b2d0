package robosim.viewer;

/**
 * What the viewer knows about the run it shows, immutable: the state, the reason (why it stopped or
 * the connection was lost; "" otherwise), and what the viewer does meanwhile (e.g. "waiting for the
 * next run on localhost:3000"; "" while connected).
 */
public record ViewedRun(Kind kind, String reason, String next) {
    /** The run's state as the viewer shows it. */
    public enum Kind { WAITING_FOR_ROBOTS, RUNNING, PAUSED, STOPPED, LOST }

    public ViewedRun {
        if (kind == null || reason == null || next == null) {
            throw new IllegalArgumentException("kind, reason and next must not be null");
        }
    }

    public static ViewedRun of(Kind kind) {
        return new ViewedRun(kind, "", "");
    }

    public ViewedRun withNext(String newNext) {
        return new ViewedRun(kind, reason, newNext);
    }
}
