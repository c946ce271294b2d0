package robosim.environment.net;

import java.io.IOException;
import java.net.Socket;
import robosim.protocol.Protocol;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Serves one robot's Hardware Simulator. Its thread does the handshake and then only reads: each
 * request goes to the coordinator, which runs the step on the thread of the last robot to arrive.
 * Every write after the hello (welcome, first step, responses, end) happens under the coordinator's
 * lock, from whichever thread holds it. A request out of turn, for the wrong step or with a
 * non-finite action drops this robot alone. That thread writes every robot's response through {@link #deliver}
 * together with the next step number (or the end), in one flush; so between steps every worker
 * thread stays parked in its socket read instead of waking up to write.
 */
final class RobotClientWorker extends ClientWorker {
    private int index = -1;

    RobotClientWorker(ClientWorkerCoordinator coordinator, Socket socket, int serial) {
        super(coordinator, socket, "robot-worker[#" + serial + "]");
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        RobotHello hello = connection.read(RobotHello.class);
        int wanted = hello.name() == null ? -1 : coordinator.spec().indexOf(hello.name());
        String refusal = coordinator.register(this, hello, wanted);
        if (refusal != null) {
            coordinator.log().warn("{} refused: {}", name(), refusal);
            connection.write(RobotWelcome.refused(refusal));
            connection.flush();
            return;
        }
        index = wanted;
        rename("robot-worker[" + hello.name() + "]");
        connection.setReadTimeoutMs(0);
        if (coordinator.sequential()) {
            // the stepper thread reads this robot's requests; this thread holds the session open
            coordinator.awaitEnd();
            return;
        }
        // read at once, also while waiting for the others: a robot that leaves before the start is noticed
        long k = 0;
        while (coordinator.accepts(index)) {
            coordinator.processMessage(index, k, readRequest(k));
            k++;
        }
    }

    /** Reads and checks this robot's request for step k (its worker's or the stepper's thread). */
    StepRequest readRequest(long k) throws IOException {
        StepRequest request = connection.read(StepRequest.class);
        if (request.step() != k) {
            throw new ProtocolException("sent a request for step " + request.step() + " where step " + k
                    + " was due");
        }
        if (!Double.isFinite(request.moveMm()) || !Double.isFinite(request.turnDeg())) {
            throw new ProtocolException("asked to move " + request.moveMm() + " mm and turn "
                    + request.turnDeg() + " deg");
        }
        return request;
    }

    /** Sends the welcome; called by the coordinator under its lock when the robot is accepted. */
    void welcome(RobotWelcome welcome) throws IOException {
        connection.write(welcome);
        connection.flush();
    }

    /** Sends the first step number; called by the coordinator under its lock when the run starts. */
    void begin(long firstStep) throws IOException {
        connection.writeStep(firstStep);
        connection.flush();
    }

    /**
     * Writes this robot's response and then the next step number, or the end of the simulation;
     * called under the coordinator's lock by the thread that ran the step.
     */
    void deliver(StepResponse response, long nextStep, SimulationEnd end) throws IOException {
        connection.write(response);
        if (end == null) {
            connection.writeStep(nextStep);
        } else {
            connection.writeStep(Protocol.END_OF_SIMULATION);
            connection.write(end);
        }
        connection.flush();
    }

    /**
     * Ends the simulation for this robot out of turn. {@code midStep}: it has been given a step number
     * and will read an object next; otherwise it is waiting for a step number.
     */
    void end(SimulationEnd end, boolean midStep) {
        try {
            if (!midStep) {
                connection.writeStep(Protocol.END_OF_SIMULATION);
            }
            connection.write(end);
            connection.flush();
        } catch (IOException | RuntimeException e) {
            coordinator.log().info("{}: could not send the end of the simulation: {}", name(), e.getMessage());
        }
    }

    @Override
    protected void exited(String why) {
        if (index >= 0) {
            coordinator.leave(this, index, why);
        }
    }
}
