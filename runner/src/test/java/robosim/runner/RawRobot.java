package robosim.runner;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.util.List;
import robosim.protocol.CommEvent;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/** A robot client by hand, one step at a time, for tests that need to know exactly which step it is in. */
final class RawRobot implements AutoCloseable {
    final String name;
    final ObjectConnection connection;
    final RobotWelcome welcome;
    /** The step number last read (-1 before the first), or {@link Protocol#END_OF_SIMULATION}. */
    long step = -1;
    /** The number of the first step it was given (-1 before it). */
    long firstStep = -1;
    String endReason;

    RawRobot(String name, RobotProperties properties, int port) throws IOException {
        this.name = name;
        this.connection = new ObjectConnection(new Socket(InetAddress.getLoopbackAddress(), port), 64);
        connection.write(new RobotHello(name, properties));
        connection.flush();
        this.welcome = connection.read(RobotWelcome.class);
    }

    /** Reads the next step number; false at the end of the simulation (its reason kept). */
    boolean next() throws IOException {
        step = connection.readStep();
        if (step == Protocol.END_OF_SIMULATION) {
            endReason = connection.read(SimulationEnd.class).reason();
            return false;
        }
        if (firstStep < 0) {
            firstStep = step;
        }
        return true;
    }

    /**
     * Sends the step's request (read with {@link #next} first) and reads its response; null when the
     * simulation ended instead (stopped mid-step: its reason kept).
     */
    StepResponse step(double moveMm, double turnDeg, boolean sonar, List<CommEvent> messages) throws IOException {
        connection.write(new StepRequest(step, moveMm, turnDeg, sonar, messages));
        connection.flush();
        java.io.Externalizable answer = connection.read(java.io.Externalizable.class);
        if (answer instanceof SimulationEnd end) {
            endReason = end.reason();
            return null;
        }
        return (StepResponse) answer;
    }

    @Override
    public void close() {
        connection.close();
    }
}
