package robosim.testhost;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.Callable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import robosim.protocol.CommandLines;
import robosim.protocol.Printable;
import robosim.protocol.link.FirstHello;

/**
 * {@code scripts/simulation-host.sh}: the testkit's simulations ({@link robosim.testkit.Simulation}) served to one
 * tester over the simulation link ({@link SimulationLink}) on loopback. Python's {@code robosim.testing} starts it
 * and reads where it listens from its first line; it serves one tester (the first whose hello carries
 * {@code ROBOSIM_LINK_KEY}, when that is set), one simulation after another or several at once, and exits when the
 * tester says bye or goes.
 */
@Command(name = "simulation-host.sh", mixinStandardHelpOptions = true,
        description = "Serves simulations of the testkit (a world run in this JVM, stepped and asked) to one tester "
                + "(Python's robosim.testing) over the simulation link on loopback.")
public final class SimulationHostMain implements Callable<Integer> {
    private static final Logger LOG = LoggerFactory.getLogger(SimulationHostMain.class);
    /** Refused hellos logged, at most (strangers on this machine may try many). */
    static final int MAX_LOGGED_REFUSALS = 8;
    /** Connections whose hellos are awaited at once (strangers beyond are closed at once). */
    static final int MAX_PENDING = 16;

    @Option(names = "--port", defaultValue = "0", description = "The simulation link's port on loopback "
            + "(default: ${DEFAULT-VALUE}: one the system picks, printed).")
    int port;

    @Option(names = "--accept-timeout-s", defaultValue = "60", description = "Exit 3 if no tester has said hello "
            + "within this long; hellos refused meanwhile (another key, another link) are logged (default: "
            + "${DEFAULT-VALUE}).")
    int acceptTimeoutS;

    @Override
    public Integer call() {
        if (port < 0 || port > 65535) {
            System.err.println("simulation-host: --port must be 0 to 65535, got " + port);
            return 2;
        }
        if (acceptTimeoutS < 1) {
            System.err.println("simulation-host: --accept-timeout-s must be >= 1, got " + acceptTimeoutS);
            return 2;
        }
        InetAddress loopback = InetAddress.getLoopbackAddress();
        try (ServerSocket server = new ServerSocket()) {
            server.bind(new InetSocketAddress(loopback, port), MAX_PENDING);
            System.out.println(SimulationLink.NAME + " listening on " + loopback.getHostAddress() + ":"
                    + server.getLocalPort());
            System.out.flush();
            return serve(server);
        } catch (IOException e) {
            System.err.println("simulation-host: " + Printable.of(String.valueOf(e.getMessage()), 1000));
            return 1;
        }
    }

    private int serve(ServerSocket server) throws IOException {
        String key = System.getenv("ROBOSIM_LINK_KEY");
        int[] refused = {0};
        FirstHello.Welcomed<SimulationLink> tester = FirstHello.await(server, acceptTimeoutS * 1000L, MAX_PENDING,
                socket -> {
                    socket.setTcpNoDelay(true);
                    SimulationLink link = new SimulationLink(socket);
                    link.welcome(key);
                    return link;
                }, why -> {
                    synchronized (refused) {
                        if (++refused[0] <= MAX_LOGGED_REFUSALS) {
                            LOG.warn("{}{}", why, refused[0] == MAX_LOGGED_REFUSALS
                                    ? " (further refusals are not logged)" : "");
                        }
                    }
                });
        if (tester == null) {
            System.err.println("simulation-host: no tester said hello within " + acceptTimeoutS + " s");
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
    }

    public static void main(String[] args) {
        CommandLines.exit("simulation-host", new SimulationHostMain(), args);
    }
}
