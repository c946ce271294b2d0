package robosim.environment.net;

import robosim.environment.server.ConnectionWatch;
import robosim.environment.server.ConnectionClock;
import java.io.IOException;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepResponse;

/**
 * {@link RobotOutput} of the report's design: the loop writes each response to the robot's socket itself,
 * on the connection's {@link ConnectionClock} (a robot that does not take a write in time is cut off by the
 * {@link ConnectionWatch}, and the write fails with that reason).
 */
final class LoopWrites implements RobotOutput {
    private final ObjectConnection connection;
    private final ConnectionClock clock;
    private final boolean stepMessages;

    LoopWrites(ObjectConnection connection, ConnectionClock clock, boolean stepMessages) {
        this.connection = connection;
        this.clock = clock;
        this.stepMessages = stepMessages;
    }

    /** Every step: written out here rather than through {@link #timed}, so the hot path allocates nothing. */
    @Override
    public void response(StepResponse response, long nextStep, SimulationEnd end) throws IOException {
        clock.writing();
        try {
            writeResponse(connection, stepMessages, response, nextStep, end);
        } catch (IOException e) {
            throw cutOffOr(e);
        } finally {
            clock.written();
        }
    }

    @Override
    public void end(SimulationEnd end, boolean midStep) throws IOException {
        timed(() -> writeEnd(connection, end, midStep));
    }

    /** Loop thread: the first step number. */
    void step(long step) throws IOException {
        timed(() -> {
            connection.writeStep(step);
            connection.flush();
        });
    }

    /** Loop thread: the welcome. */
    void welcome(RobotWelcome welcome) throws IOException {
        timed(() -> {
            connection.write(welcome);
            connection.flush();
        });
    }

    /** One write to the robot. */
    private interface Write {
        void run() throws IOException;
    }

    /** {@code write} on the connection's clock; its failure carries the watch's reason if it cut the robot off. */
    private void timed(Write write) throws IOException {
        clock.writing();
        try {
            write.run();
        } catch (IOException e) {
            throw cutOffOr(e);
        } finally {
            clock.written();
        }
    }

    /** The failure of a write: the watch's reason if it cut the robot off, else {@code e} itself. */
    private IOException cutOffOr(IOException e) {
        String why = clock.cutOffReason();
        return why == null ? e : new IOException(why, e);
    }

    @Override
    public void close() {
    }

    /** A response, then the next step number (unless step messages are off) or the end, in one flush. */
    static void writeResponse(ObjectConnection c, boolean stepMessages, StepResponse response, long nextStep,
            SimulationEnd end) throws IOException {
        c.write(response);
        if (end == null) {
            if (stepMessages) {
                c.writeStep(nextStep);
            }
        } else {
            if (stepMessages) {
                c.writeStep(Protocol.END_OF_SIMULATION);
            }
            c.write(end);
        }
        c.flush();
    }

    /** The end out of turn; {@code midStep}: the robot will read an object next, not a step number. */
    static void writeEnd(ObjectConnection c, SimulationEnd end, boolean midStep) throws IOException {
        if (!midStep) {
            c.writeStep(Protocol.END_OF_SIMULATION);
        }
        c.write(end);
        c.flush();
    }
}
