package robosim.environment.run;

import java.io.IOException;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepResponse;

/**
 * One robot as the {@link Run} sees it, whatever carries it ({@link Transport}): where its welcome, step numbers,
 * responses and end go. {@link RobotConnection} is the one over a socket of its own, {@link SharedRobot} one of a
 * shared connection, {@link InMemoryPeer} one in the Environment's JVM; the run never reads from a robot, it is
 * handed requests as events, and never asks which kind a robot is.
 */
public interface RobotPeer {
    /** Its place in the world's robot list (-1 before it has said hello). */
    int index();

    /** Loop thread, as it accepts the hello: its place in the world's robot list. */
    void assign(int index);

    void welcome(RobotWelcome welcome) throws IOException;

    /**
     * Its hello is refused for {@code why} (the loop completes its verdict too): a peer whose own thread writes the
     * refusal does nothing; a robot of a shared connection puts it into the connection's frame.
     */
    default void refused(String why) {
    }

    /** Sends the first step number. */
    void begin(long firstStep) throws IOException;

    /** Its response and then the next step number, or the end ({@code end} not null). */
    void deliver(StepResponse response, long nextStep, SimulationEnd end) throws IOException;

    /** The end out of turn; {@code midStep}: it has a step number and reads an object next. */
    void end(SimulationEnd end, boolean midStep);

    /** True once it has been given a step number. */
    boolean begun();

    /** True once its connection has closed. */
    boolean closed();

    /**
     * The loop drops it: closes its connection (a robot of a shared connection is told its end instead, and
     * what it sends after is ignored; the connection's other robots go on).
     */
    void drop();
}
