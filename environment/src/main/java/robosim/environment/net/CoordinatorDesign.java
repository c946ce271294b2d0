package robosim.environment.net;

/**
 * How robots' requests are read and responses written, the report's coordinator designs:
 * {@code THREADS} (the default, the paper's design): one thread per robot reads its requests, the
 * loop writes every response; {@code SEQUENTIAL}, the original's loop: one {@code stepper} thread
 * reads every robot's request in world order; {@code TWO_THREADS}: per robot one thread reads and one
 * ({@code robot-writer[name]}) writes what the loop queues. Each is one {@link Design} class; this is the
 * user's choice of it.
 */
public enum CoordinatorDesign {
    THREADS, SEQUENTIAL, TWO_THREADS;

    /** Null if this design can handle a lost robot as {@code policy} says, else why not. */
    public String refusesLossPolicy(RobotLoss policy) {
        return Design.of(this).refusesLossPolicy(policy);
    }
}
