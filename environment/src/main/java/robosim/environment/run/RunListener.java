package robosim.environment.run;

/** Told, on the loop thread, what happens in the run; must not block. */
public interface RunListener {
    default void started(int robots) {
    }

    default void robotLeft(Departure departure) {
    }

    /** A robot was lost and stays in the world for its return ({@code --on-robot-loss HOLD} or {@code WAIT}). */
    default void robotHeld(String robot, long step, String why) {
    }

    /** A robot joined the running world; it takes part from the next step. */
    default void robotJoined(String robot, long step) {
    }

    /** A lost robot's new connection takes part again from {@code step}. */
    default void robotReturned(String robot, long step) {
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
