package robosim.testhost;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.Callable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import robosim.protocol.CommandLines;
import robosim.protocol.Printable;
import robosim.protocol.link.FirstHello;

/**
 * {@code scripts/simulation-host.sh}: the testkit's simulations ({@link robosim.testkit.Simulation}) served to one
 * tester over the simulation link ({@link SimulationLink}) on loopback. Python's {@code robosim.testing} starts it
 * and reads where it listens from its first line; it serves one tester (the first whose hello carries
 * {@code ROBOSIM_LINK_KEY}, which must be set: its tester runs worlds and writes files as this user), one simulation
 * after another or several at once, and exits when the tester says bye or goes.
 */
@Command(name = "simulation-host.sh", mixinStandardHelpOptions = true,
        description = "Serves simulations of the testkit (a world run in this JVM, stepped and asked) to one tester "
                + "(Python's robosim.testing) over the simulation link on loopback.")
public final class SimulationHostMain implements Callable<Integer> {
    private static final Logger LOG = LoggerFactory.getLogger(SimulationHostMain.class);

    @Mixin
    robosim.runner.LinkHostOptions host;

    @Override
    public Integer call() {
        if (host.problem() != null) {
            System.err.println("simulation-host: " + host.problem());
            return 2;
        }
        String key = System.getenv("ROBOSIM_LINK_KEY");
        if (key == null || key.isBlank()) { // (its peer runs worlds and writes files as this user: it must prove it)
            System.err.println("simulation-host: needs ROBOSIM_LINK_KEY, the secret its tester's hello carries "
                    + "(Python's robosim.testing gives it one); none is set");
            return 2;
        }
        try (ServerSocket server = host.listen()) {
            System.out.println(SimulationLink.NAME + " listening on " + server.getInetAddress().getHostAddress() + ":"
                    + server.getLocalPort());
            System.out.flush();
            FirstHello.Welcomed<SimulationLink> tester = host.awaitPeer(server, socket -> {
                socket.setTcpNoDelay(true);
                SimulationLink link = new SimulationLink(socket);
                link.welcome(key);
                return link;
            }, LOG);
            if (tester == null) {
                System.err.println("simulation-host: no tester said hello within " + host.acceptTimeoutS() + " s");
                return 3;
            }
            try (Socket socket = tester.socket()) {
                long requests = tester.link().serve();
                LOG.info("served {} requests; the tester has gone", requests);
                return 0;
            } catch (IOException e) {
                System.err.println("simulation-host: the simulation link failed: " + Printable.of(e.getMessage(), 1000));
                return 1;
            }
        } catch (IOException e) {
            System.err.println("simulation-host: " + Printable.of(String.valueOf(e.getMessage()), 1000));
            return 1;
        }
    }

    public static void main(String[] args) {
        CommandLines.exit("simulation-host", new SimulationHostMain(), args);
    }
}
