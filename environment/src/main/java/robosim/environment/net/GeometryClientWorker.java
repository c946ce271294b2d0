package robosim.environment.net;

import java.io.IOException;
import java.net.Socket;
import robosim.environment.core.GeometryService;
import robosim.protocol.GeometryHello;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.GeometryWorld;
import robosim.protocol.Protocol;
import robosim.protocol.SimulationEnd;

/**
 * Serves the Geometry process. Its thread does the handshake and then holds the session open until
 * the simulation ends; each step's round trip ({@link #resolve}) runs on the thread that releases
 * the step, which would only wait for it otherwise.
 */
final class GeometryClientWorker extends ClientWorker implements GeometryService {
    GeometryClientWorker(ClientWorkerCoordinator coordinator, Socket socket) {
        super(coordinator, socket, "geometry-worker");
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        GeometryHello hello = connection.read(GeometryHello.class);
        connection.setReadTimeoutMs(0);
        String refusal = hello.protocolVersion() != Protocol.VERSION
                ? "protocol version " + hello.protocolVersion() + " is not supported (the Environment speaks "
                        + Protocol.VERSION + ")"
                : coordinator.attachGeometry(this);
        if (refusal != null) {
            coordinator.log().warn("{} refused: {}", name(), refusal);
            connection.write(new SimulationEnd(-1, refusal));
            connection.flush();
            return;
        }
        coordinator.awaitEnd();
    }

    /** Sends the world; called once, by the coordinator, when the run starts. */
    void sendWorld(GeometryWorld world) throws IOException {
        connection.write(world);
        connection.flush();
    }

    void sendEnd(SimulationEnd end) {
        try {
            connection.write(end);
            connection.flush();
        } catch (IOException e) {
            coordinator.log().info("geometry-worker: could not send the end of the simulation: {}", e.getMessage());
        }
    }

    private volatile long busySince;

    @Override
    public GeometryStepResponse resolve(GeometryStepRequest request) throws IOException {
        busySince = System.nanoTime();
        try {
            connection.write(request);
            connection.flush();
            return connection.read(GeometryStepResponse.class);
        } finally {
            busySince = 0;
        }
    }

    /** How long the current step's round trip has taken so far, ns; 0 if none is under way. */
    long busyFor(long now) {
        long since = busySince;
        return since == 0 ? 0 : now - since;
    }

    @Override
    protected void exited(String why) {
        coordinator.geometryExited(this, why);
    }
}
