package robosim.environment.net;

import robosim.environment.run.GeometryPeer;
import robosim.environment.run.LoopEvent;
import robosim.environment.run.SimulationLoop;
import robosim.environment.server.ClientWorker;
import robosim.environment.server.Port;
import robosim.environment.server.ServerContext;
import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.protocol.GeometryHello;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.GeometryWorld;
import robosim.protocol.SimulationEnd;

/**
 * Serves the Geometry process on its own thread, {@code geometry-worker}, which owns that connection:
 * after the handshake it does what the {@code GeometryLink} asks, one task at a time - send the world,
 * do a step's round trip (write the request, read the answer) and hand the answer to the loop, send
 * the end - and while idle looks a few times a second whether its process has closed the connection
 * (then it is lost at once, and a new Geometry process may attach). The simulation loop never touches this socket, so a Geometry process that hangs holds up
 * nobody but the step that waits for it, and only until the Geometry timeout.
 */
final class GeometryClientWorker extends ClientWorker implements GeometryPeer {
    private record SendWorld(GeometryWorld world) {
    }

    private record Resolve(GeometryStepRequest request) {
    }

    private record End(SimulationEnd end) {
    }

    /** How often an idle worker looks whether its Geometry process is still there, ms. */
    private static final long IDLE_LOOK_MS = 250;

    /** At most two worlds (the first and one after robots joined), one step and the end are ever outstanding. */
    private final BlockingQueue<Object> tasks = new ArrayBlockingQueue<>(4);

    private final SimulationLoop loop;

    GeometryClientWorker(ServerContext server, SimulationLoop loop, Socket socket) {
        super(server, socket, "geometry-worker", Port.GEOMETRY);
        this.loop = loop;
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        GeometryHello hello = (GeometryHello) handshake.hello(port);
        String refusal = handshake.heard("geometry");
        if (refusal == null) {
            refusal = handshake.version(hello.protocolVersion());
        }
        if (refusal == null) {
            CompletableFuture<String> verdict = new CompletableFuture<>();
            loop.post(new LoopEvent.GeometryJoins(this, verdict));
            refusal = handshake.verdict(verdict);
        }
        if (refusal != null) {
            handshake.refused(refusal);
            send(new SimulationEnd(-1, refusal));
            return;
        }
        handshake.accepted();
        while (true) {
            Object task = tasks.poll(IDLE_LOOK_MS, TimeUnit.MILLISECONDS);
            if (task == null) {
                // idle (paused, or a step still gathering): notice a Geometry process that has gone, so a
                // new one may attach at once instead of being refused as a second one
                if (connection.closedByPeerWithin(1)) {
                    throw new java.io.EOFException("the Geometry process closed the connection");
                }
                continue;
            }
            if (task instanceof SendWorld w) {
                send(w.world());
                loop.post(new LoopEvent.GeometryReady(this));
            } else if (task instanceof Resolve r) {
                send(r.request());
                GeometryStepResponse answer = connection.read(GeometryStepResponse.class);
                loop.post(new LoopEvent.GeometryAnswer(this, answer));
            } else {
                send(((End) task).end());
                return;
            }
        }
    }

    @Override
    public void sendWorld(GeometryWorld world) {
        tasks.add(new SendWorld(world));
    }

    @Override
    public void resolve(GeometryStepRequest request) {
        tasks.add(new Resolve(request));
    }

    @Override
    public void end(SimulationEnd end) {
        if (!tasks.offer(new End(end))) {
            drop();
        }
    }

    @Override
    protected void exited(String why) {
        loop.post(new LoopEvent.GeometryLeaves(this, why));
    }
}
