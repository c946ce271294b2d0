package robosim.geometry;

import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.Callable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.protocol.CommandLines;
import robosim.protocol.ClientOptions;
import robosim.protocol.Connector;
import robosim.protocol.SimulationKeys;
import robosim.protocol.Protocol;

/** {@code scripts/geometry.sh HOST PORT}: the Geometry process, a client of the Environment. */
@Command(name = "geometry.sh", mixinStandardHelpOptions = true,
        description = "Connects to an Environment's geometry port and does its collision detection and sonar "
                + "ranging until the simulation ends.")
public final class GeometryMain implements Callable<Integer> {
    private static final Logger LOG = LoggerFactory.getLogger(GeometryMain.class);

    @Parameters(index = "0", defaultValue = "localhost", description = "Environment host (default: ${DEFAULT-VALUE}).")
    String host;

    @Parameters(index = "1", defaultValue = "" + Protocol.DEFAULT_GEOMETRY_PORT,
            description = "Environment geometry port (default: ${DEFAULT-VALUE}).")
    int port;

    @Mixin
    ClientOptions connection;

    @Option(names = "--split-sonar-from", paramLabel = "ROBOTS",
            description = "Split each step's sonar pass over two cores when at least this many robots ask for sonar; "
                    + "0 never (default: " + GeometryEngine.DEFAULT_PARALLEL_FROM + " with two cores or more, else 0). "
                    + "The ranges are the same either way.")
    Integer splitSonarFrom;

    @Override
    public Integer call() throws Exception {
        if (splitSonarFrom != null && splitSonarFrom < 0) {
            System.err.println("geometry: --split-sonar-from " + splitSonarFrom + " is negative (0 turns it off)");
            return 2;
        }
        if (Connector.badPort(port) != null) {
            System.err.println("geometry: " + host + ":" + port + ": " + Connector.badPort(port));
            return 2;
        }
        Socket socket;
        try {
            socket = Connector.connect(host, port, connection.connect().millis(), System.err::println);
        } catch (IOException e) {
            System.err.println("geometry: cannot connect to " + host + ":" + port + ": " + e.getMessage());
            return e instanceof java.net.UnknownHostException ? 2 : 1;
        }
        if (socket == null) {
            System.err.println("geometry: cannot connect to " + host + ":" + port + " within "
                    + connection.connect().seconds()
                    + " s (is the Environment running?)");
            return 1;
        }
        String reason;
        GeometryClient client;
        try {
            client = new GeometryClient(socket, connection.resetEvery(), SimulationKeys.fromEnvironment(),
                    connection.connect().millis());
            if (splitSonarFrom != null) {
                client.splitSonarFrom(splitSonarFrom);
            }
            reason = client.run();
        } catch (IOException e) {
            System.err.println("geometry: " + host + ":" + port + ": " + e.getMessage());
            return 1;
        }
        LOG.info("session over after {} steps: {}", client.steps(), reason);
        return 0;
    }

    public static void main(String[] args) {
        CommandLines.exit("geometry", new GeometryMain(), args);
    }
}
