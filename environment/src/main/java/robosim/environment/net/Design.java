package robosim.environment.net;

import java.io.IOException;

/**
 * One of the report's coordinator designs: how robots' requests are read and responses written. Chosen
 * once at start-up ({@link #of}); the {@link Run}, the {@link SimulationLoop} and the robot workers ask it
 * and hold no branch on which one runs. {@link ThreadsDesign} (the paper's, the default),
 * {@link SequentialDesign} (the original's loop), {@link TwoThreadsDesign} (a reader and a writer per robot).
 */
interface Design {
    static Design of(CoordinatorDesign choice) {
        return switch (choice) {
            case THREADS -> new ThreadsDesign();
            case SEQUENTIAL -> new SequentialDesign();
            case TWO_THREADS -> new TwoThreadsDesign();
        };
    }

    /** Null if robots may join a running world, else why not. */
    default String refusesJoins() {
        return null;
    }

    /** Null if several robots may share one connection, else why not. */
    default String refusesSharedConnections() {
        return null;
    }

    /** Null if a lost robot may be handled by {@code policy}, else why not. */
    default String refusesLossPolicy(RobotLoss policy) {
        return null;
    }

    /** True if robots' requests are read in world order, so only the first robot not heard from is late. */
    default boolean readsInWorldOrder() {
        return false;
    }

    /** Loop thread: step 0 has gone out to every robot of {@code roster}. */
    default void begun(ClientWorkerCoordinator coordinator, Roster roster) {
    }

    /**
     * A robot worker's thread, once its robot is welcomed: reads that robot's requests and posts them to the
     * loop until the connection ends (or leaves them to whoever reads them in this design).
     */
    default void read(RobotConnection robot, ClientWorkerCoordinator coordinator)
            throws IOException, InterruptedException {
        for (long k = RobotConnection.FIRST; ; k++) {
            robosim.protocol.StepRequest request = robot.readRequest(k);
            k = request.step();
            coordinator.post(new LoopEvent.Request(robot, request));
        }
    }

    /**
     * Loop thread, as {@code robot} (over a socket of its own) is welcomed: what writes its responses from now
     * on; {@code loopWrites}, the loop's own writes, unless this design has a thread for them.
     */
    default RobotOutput output(RobotConnection robot, LoopWrites loopWrites, robosim.protocol.ObjectConnection connection,
            boolean stepMessages, String robotName) {
        return loopWrites;
    }
}
