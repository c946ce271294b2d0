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
 * Serves one robot's Hardware Simulator: the handshake, then per step k: send k (a primitive long),
 * read the robot's request, hand it to the coordinator (which may run the step on this thread), and
 * write the response together with the next step number in one flush.
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
        if (!coordinator.awaitStart()) {
            sendEnd();
            return;
        }
        long k = coordinator.firstStep();
        connection.writeStep(k);
        connection.flush();
        while (true) {
            StepRequest request = connection.read(StepRequest.class);
            StepResponse response = coordinator.processMessage(index, k, request);
            if (response == null) {
                connection.write(coordinator.endMessage());
                connection.flush();
                return;
            }
            connection.write(response);
            k++;
            if (!coordinator.isRunning()) {
                sendEnd();
                return;
            }
            connection.writeStep(k);
            connection.flush();
        }
    }

    private void sendEnd() throws IOException {
        connection.writeStep(Protocol.END_OF_SIMULATION);
        SimulationEnd end = coordinator.endMessage();
        connection.write(end);
        connection.flush();
    }

    @Override
    protected void exited(String why) {
        if (index >= 0) {
            coordinator.leave(this, index, why);
        }
    }
}
