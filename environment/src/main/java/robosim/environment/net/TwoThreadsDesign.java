package robosim.environment.net;

/**
 * {@code TWO_THREADS}: per robot one thread reads its requests (as {@link ThreadsDesign}) and one,
 * {@code robot-writer[name]} ({@link RobotWriter}), writes what the loop queues, so responses go out in
 * parallel and the loop never writes a response to a socket.
 */
final class TwoThreadsDesign implements Design {
    @Override
    public RobotOutput output(RobotConnection robot, LoopWrites loopWrites, boolean stepMessages) {
        return new RobotWriter(robot, stepMessages);
    }
}
