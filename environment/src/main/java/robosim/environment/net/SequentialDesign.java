package robosim.environment.net;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code SEQUENTIAL}, the original's loop: one thread, {@code stepper} ({@link SequentialReader}), reads
 * every robot's request in world order from step 1 on; each robot's worker reads only its step-0 request
 * (so a robot that leaves before the start is noticed) and then holds its session until the end. Its list of
 * robots is fixed at the start: no robot joins, none is held for its return, no connection is shared.
 */
final class SequentialDesign implements Design {
    @Override
    public String refusesJoins() {
        return "robots cannot join this run: its SEQUENTIAL coordinator reads a fixed list of robots (THREADS or "
                + "TWO_THREADS can)";
    }

    @Override
    public String refusesSharedConnections() {
        return "a shared connection needs the THREADS or TWO_THREADS coordinator (SEQUENTIAL reads a socket per "
                + "robot; run the robots with --connection PER_ROBOT)";
    }

    @Override
    public String refusesLossPolicy(RobotLoss policy) {
        return policy == RobotLoss.REMOVE ? null : "--on-robot-loss " + policy + " needs the THREADS or "
                + "TWO_THREADS coordinator: the SEQUENTIAL loop reads a fixed list of robots";
    }

    @Override
    public boolean readsInWorldOrder() {
        return true;
    }

    @Override
    public void begun(ClientWorkerCoordinator coordinator, Roster roster) {
        List<RobotConnection> workers = new ArrayList<>(roster.size());
        for (RobotSlot s : roster.all()) {
            workers.add((RobotConnection) s.peer);
        }
        SequentialReader.start(coordinator, workers);
    }

    @Override
    public void read(RobotConnection robot, ClientWorkerCoordinator coordinator)
            throws IOException, InterruptedException {
        try {
            coordinator.post(new LoopEvent.Request(robot, robot.readRequest(0)));
        } finally {
            robot.firstRead(); // the stepper may read this connection from now on
        }
        coordinator.awaitEnd(); // the stepper reads the rest; this thread holds the session
    }
}
