package robosim.environment.net;

import java.io.IOException;
import java.net.Socket;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Serves one robot's Hardware Simulator. Its thread does the handshake, sends the first step number
 * and then only reads: each request goes to the coordinator, which runs the step on the thread of
 * the last robot to arrive. That thread writes every robot's response through {@link #deliver}
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
        String refusal = coordinator.register(this, hello);
        if (refusal != null) {
            coordinator.log().warn("{} refused: {}", name(), refusal);
            connection.write(RobotWelcome.refused(refusal));
            connection.flush();
            return;
        }
        rename("robot-worker[" + hello.name() + "]");
        index = coordinator.spec().indexOf(hello.name());
        WorldSpec.RobotSpec r = coordinator.spec().robots().get(index);
        connection.write(RobotWelcome.accepted(coordinator.spec().timeStepMs(), r.xMm(), r.yMm(), r.headingDeg(),
                coordinator.robotNames()));
        connection.flush();
        connection.setReadTimeoutMs(0);
        long k = coordinator.awaitStart(this, index);
        if (k < 0) {
            return;
        }
        while (coordinator.accepts(index)) {
            StepRequest request = connection.read(StepRequest.class);
            coordinator.processMessage(index, k, request);
            k++;
        }
    }

    /** Sends the first step number; called by this worker's thread, under the coordinator's lock. */
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
        } catch (IOException e) {
            coordinator.log().info("{}: could not send the end of the simulation: {}", name(), e.getMessage());
        }
    }

    /** Closes the connection, so this worker's blocked read ends. */
    void drop() {
        connection.close();
    }

    @Override
    protected void exited(String why) {
        if (index >= 0) {
            coordinator.leave(this, index, why);
        }
    }
}
