package robosim.environment.net;

import robosim.environment.run.LoopEvent;
import robosim.environment.run.SimulationLoop;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * {@code SEQUENTIAL}, the original's loop: one thread, {@code stepper} ({@link SequentialReader}), reads
 * every robot's request in world order from step 1 on; each robot's worker reads only its step-0 request
 * (so a robot that leaves before the start is noticed) and then holds its session until the end. Its list of
 * robots is fixed at the start: the robots welcomed over sockets of their own that are still connected, in world
 * order. No robot joins, none is held for its return, no connection is shared, no robot runs in the Environment's
 * JVM ({@link CoordinatorDesign} says so).
 */
final class SequentialDesign implements Design {
    private final SimulationLoop loop;
    /** Loop thread: every robot welcomed so far. */
    private final List<RobotConnection> welcomed = new ArrayList<>();

    SequentialDesign(SimulationLoop loop) {
        this.loop = loop;
    }

    @Override
    public RobotOutput output(RobotConnection robot, LoopWrites loopWrites, boolean stepMessages) {
        welcomed.add(robot);
        return loopWrites;
    }

    /** Loop thread, once step 0 has gone out: the stepper starts over the run's robots, in world order. */
    @Override
    public void started(int robots) {
        List<RobotConnection> run = new ArrayList<>();
        for (RobotConnection r : welcomed) {
            if (r.index() >= 0 && !r.closed()) { // (one that left before the start was welcomed too)
                run.add(r);
            }
        }
        run.sort(Comparator.comparingInt(RobotConnection::index));
        welcomed.clear();
        SequentialReader.start(loop, run);
    }

    @Override
    public void read(RobotConnection robot, SimulationLoop on) throws IOException, InterruptedException {
        try {
            on.post(new LoopEvent.Request(robot, robot.readRequest()));
        } finally {
            robot.firstRead(); // the stepper may read this connection from now on
        }
        on.awaitEnd(); // the stepper reads the rest; this thread holds the session
    }
}
