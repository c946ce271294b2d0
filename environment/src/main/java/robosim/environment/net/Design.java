package robosim.environment.net;

import robosim.environment.run.LoopEvent;
import robosim.environment.run.RunListener;
import robosim.environment.run.SimulationLoop;
import java.io.IOException;

/**
 * One of the report's coordinator designs, as threads: who reads a robot's socket and who writes it. Chosen once
 * per run by the facade from the {@link CoordinatorDesign}; the robot's connection asks it, and the {@link Run} never does.
 * {@link ThreadsDesign} (the paper's, the default), {@link SequentialDesign} (the original's loop),
 * {@link TwoThreadsDesign} (a reader and a writer per robot). It hears the run's events it needs (a
 * {@link RunListener}: SEQUENTIAL starts its stepper once step 0 is out).
 */
interface Design extends RunListener {
    /**
     * A robot worker's thread, once its robot is welcomed: reads that robot's requests and posts them to the
     * loop until the connection ends (or leaves them to whoever reads them in this design).
     */
    default void read(RobotConnection robot, SimulationLoop loop) throws IOException, InterruptedException {
        while (true) {
            loop.post(new LoopEvent.Request(robot, robot.readRequest()));
        }
    }

    /**
     * Loop thread, as {@code robot} (over a socket of its own) is welcomed: what writes its responses from now
     * on; {@code loopWrites}, the loop's own writes, unless this design has a thread for them.
     */
    default RobotOutput output(RobotConnection robot, LoopWrites loopWrites, boolean stepMessages) {
        return loopWrites;
    }
}
