package robosim.geometry;

import java.io.EOFException;
import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.GeometryHello;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.GeometryWorld;
import robosim.protocol.ObjectConnection;
import robosim.protocol.ProtocolException;
import robosim.protocol.SimulationKeys;
import robosim.protocol.SimulationEnd;

/**
 * The Geometry process's one session with an Environment, on the caller's thread: hello, the
 * world, then one request and one response per step (and the world again whenever robots join) until the
 * Environment ends the simulation.
 */
public final class GeometryClient {
    private static final Logger LOG = LoggerFactory.getLogger(GeometryClient.class);

    private final ObjectConnection connection;
    private long steps;
    private final SimulationKeys secret;

    public GeometryClient(Socket socket, int resetEvery) throws IOException {
        this(socket, resetEvery, SimulationKeys.fromEnvironment());
    }

    /** As above, proving {@code secret} if the Environment asks for one (null: this process has none). */
    public GeometryClient(Socket socket, int resetEvery, SimulationKeys secret) throws IOException {
        this(socket, resetEvery, secret, ObjectConnection.DEFAULT_ANSWER_MS);
    }

    /** As above, the Environment's first bytes awaited at most {@code answerWithinMs} (the connect timeout). */
    GeometryClient(Socket socket, int resetEvery, SimulationKeys secret, long answerWithinMs) throws IOException {
        this.connection = ObjectConnection.client(socket, resetEvery, secret, answerWithinMs);
        this.secret = secret;
    }

    private int splitSonarFrom = Runtime.getRuntime().availableProcessors() > 1 ? GeometryEngine.DEFAULT_PARALLEL_FROM : 0;

    /** Splits each step's sonar pass over two cores from this many robots asking for sonar (0: never). */
    public GeometryClient splitSonarFrom(int robots) {
        splitSonarFrom = robots;
        return this;
    }

    /**
     * Runs the session; returns the Environment's reason for ending it. A refusal (a port of another kind, the
     * wrong keys, another Geometry already there) is a {@link ProtocolException} giving the Environment's reason.
     */
    public String run() throws IOException {
        try (connection) {
            connection.write(new GeometryHello());
            connection.flush();
            Externalizable first = connection.answerChallenge(secret, "geometry");
            if (first instanceof SimulationEnd end) {
                throw new ProtocolException(end.reason());
            }
            if (!(first instanceof GeometryWorld world)) {
                throw new ProtocolException("expected a GeometryWorld, got a " + first.getClass().getSimpleName());
            }
            GeometryEngine engine = new GeometryEngine(world, splitSonarFrom);
            GeometryStepResponse response = engine.newResponse();
            LOG.info("world received: {} robots, {} obstacles", engine.robotCount(), world.obstacles().size());
            while (true) {
                Externalizable m;
                try {
                    m = connection.read(Externalizable.class);
                } catch (EOFException e) {
                    return "the Environment closed the connection after " + steps + " steps";
                }
                if (m instanceof SimulationEnd end) {
                    return end.reason();
                }
                if (m instanceof GeometryWorld grown) { // robots joined: the world from the next step on
                    engine = new GeometryEngine(grown, splitSonarFrom);
                    response = engine.newResponse();
                    LOG.info("world received again: {} robots", engine.robotCount());
                    continue;
                }
                if (!(m instanceof GeometryStepRequest request)) {
                    throw new ProtocolException("expected a GeometryStepRequest, got a "
                            + m.getClass().getSimpleName());
                }
                try {
                    engine.step(request, response);
                } catch (IllegalArgumentException e) {
                    throw new ProtocolException(e.getMessage());
                }
                connection.write(response);
                connection.flush();
                steps++;
            }
        }
    }

    public long steps() {
        return steps;
    }
}
