package robosim.environment.run;

/**
 * How robots' requests are read and responses written, the report's coordinator designs:
 * {@code THREADS} (the default, the paper's design): one thread per robot reads its requests, the
 * loop writes every response; {@code SEQUENTIAL}, the original's loop: one {@code stepper} thread
 * reads every robot's request in world order; {@code TWO_THREADS}: per robot one thread reads and one
 * ({@code robot-writer[name]}) writes what the loop queues. Each is one {@link Design} class for the threads
 * (chosen by the facade); this is the user's choice of it, and what the choice allows: which {@link Transport}s, which loss policies,
 * whether robots join a running world. {@link Settings} holds the choice to it once, where the Environment is
 * configured.
 */
public enum CoordinatorDesign {
    THREADS, SEQUENTIAL, TWO_THREADS;

    /** Null if robots may reach the Environment by {@code transport} under this design, else why not. */
    public String refuses(Transport transport) {
        if (this != SEQUENTIAL) {
            return null;
        }
        return switch (transport) {
            case SOCKET -> null;
            case SHARED -> "a shared connection needs the THREADS or TWO_THREADS coordinator (SEQUENTIAL reads a "
                    + "socket per robot; run the robots with --connection PER_ROBOT)";
            case IN_MEMORY -> "--one-jvm runs its robots in memory; --coordinator SEQUENTIAL reads a socket per robot "
                    + "(use THREADS or TWO_THREADS, which serve robots that join over the robot port)";
        };
    }

    /** Null if this design can handle a lost robot as {@code policy} says, else why not. */
    public String refusesLossPolicy(RobotLoss policy) {
        return this != SEQUENTIAL || policy == RobotLoss.REMOVE ? null : "--on-robot-loss " + policy + " needs the "
                + "THREADS or TWO_THREADS coordinator: the SEQUENTIAL loop reads a fixed list of robots";
    }

    /** Null if robots may join a running world, else why not. */
    public String refusesJoins() {
        return this != SEQUENTIAL ? null : "robots cannot join this run: its SEQUENTIAL coordinator reads a fixed "
                + "list of robots (THREADS or TWO_THREADS can)";
    }

    /** True if robots' requests are read in world order, so only the first robot not heard from is late. */
    boolean readsInWorldOrder() {
        return this == SEQUENTIAL;
    }
}
