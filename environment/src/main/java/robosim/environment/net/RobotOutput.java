package robosim.environment.net;

import java.io.IOException;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepResponse;

/**
 * How the loop's responses reach one robot over its own socket, as its {@link Design} says: written by the
 * loop itself ({@link LoopWrites}) or queued to a writer thread of the robot's ({@link RobotWriter}).
 */
interface RobotOutput {
    /** Loop thread: a response, then the next step number (unless step messages are off) or the end. */
    void response(StepResponse response, long nextStep, SimulationEnd end) throws IOException;

    /** Loop thread: the end out of turn; {@code midStep}: the robot will read an object next, not a step number. */
    void end(SimulationEnd end, boolean midStep) throws IOException;

    /** The robot's reading thread is done: what is still to write goes out (briefly), then nothing more. */
    void close() throws InterruptedException;
}
