package robosim.environment.run;

/**
 * What a robots' transport does on the loop thread between events, where it needs to (a socket per robot needs
 * nothing): the {@link SimulationLoop} calls every hook after each event and each deadline check, once the run
 * has moved on as far as it can. Robots in this JVM hand in the requests built without an event
 * ({@link InMemoryTransport}); shared connections write the frame the loop filled for each ({@link SharedOutput}).
 * The {@link Run} knows no hook.
 */
public interface LoopHook {
    /**
     * Hands the run what came without an event; true if it handed in anything (the run moves on again).
     * {@code deadline}: before the deadlines are judged, so everything that has come is taken (it is not late).
     */
    default boolean handIn(Run run, boolean deadline) {
        return false;
    }

    /** Writes what the loop has buffered for this transport's robots, once the run has moved on. */
    default void flush() {
    }

    /** True while it has something to hand in at once: the loop looks again without waiting for an event. */
    default boolean pending() {
        return false;
    }
}
