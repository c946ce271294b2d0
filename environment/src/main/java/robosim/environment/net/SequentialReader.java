package robosim.environment.net;

import robosim.environment.run.LoopEvent;
import robosim.environment.run.SimulationLoop;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code SEQUENTIAL}, the original's loop: one thread, {@code stepper}, reads every robot's request in
 * world order, from step 1 on (each robot's worker reads its step-0 request, so a robot that leaves
 * before the start is noticed), and hands each to the {@link SimulationLoop}. A read blocks until that
 * robot has had its response and answered, which is what orders the steps; a robot whose read fails or
 * who breaks the protocol is dropped and skipped from then on. The thread ends with the simulation.
 */
final class SequentialReader implements Runnable {
    private final SimulationLoop loop;
    private final List<RobotConnection> robots;

    private SequentialReader(SimulationLoop loop, List<RobotConnection> robots) {
        this.loop = loop;
        this.robots = robots;
    }

    /** Starts the {@code stepper} thread over {@code robots} (workers over sockets), in world order. */
    static void start(SimulationLoop loop, List<RobotConnection> robots) {
        Thread t = new Thread(new SequentialReader(loop, List.copyOf(robots)), "stepper");
        t.setDaemon(true);
        t.start();
    }

    @Override
    public void run() {
        try {
            readAll();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Reads step after step. What it has read is handed over in one batch, just before a read that would
     * block (and at the end of the step): the loop wakes once for all the requests that were already
     * there, and always knows which robot the stepper waits for (the first without a request).
     */
    private void readAll() throws InterruptedException {
        List<LoopEvent> batch = new ArrayList<>();
        for (long k = 1; !loop.over(); k++) {
            boolean anyone = false;
            for (RobotConnection robot : robots) {
                if (robot.dropped() || loop.over()) {
                    continue;
                }
                anyone = true;
                try {
                    if (k == 1) {
                        robot.awaitFirstRead();
                    }
                    if (!batch.isEmpty() && !robot.hasInput()) {
                        handOver(batch);
                    }
                    batch.add(new LoopEvent.Request(robot, robot.readRequest()));
                } catch (IOException e) {
                    robot.drop();
                    batch.add(new LoopEvent.RobotLeaves(robot, e.getMessage() == null ? e.toString() : e.getMessage()));
                }
            }
            handOver(batch);
            if (!anyone) {
                return;
            }
        }
    }

    private void handOver(List<LoopEvent> batch) {
        if (!batch.isEmpty()) {
            loop.post(new LoopEvent.Batch(List.copyOf(batch)));
            batch.clear();
        }
    }
}
