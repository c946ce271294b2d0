package robosim.environment.net;

/** Told, on the loop thread, what happens in the run; must not block. */
public interface RunListener {
    default void started(int robots) {
    }

    default void robotLeft(Departure departure) {
    }

    default void geometryLost(long step) {
    }

    default void geometryAttached(long step) {
    }

    default void viewerDropped(String viewer, String why) {
    }

    /** A step is held because a recording viewer has fallen its whole backlog behind. */
    default void heldForViewer(long step) {
    }

    default void ended(RunSummary summary) {
    }
}
