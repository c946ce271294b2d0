package robosim.runner;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.function.Consumer;
import robosim.protocol.ObjectConnection;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationKeys;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.ViewerHello;

/** The soak's misbehaving clients, driven by hand, and the one external command it runs (jcmd). */
final class SoakClients {
    private SoakClients() {
    }

    /** A robot driven by hand that answers until step {@code silentAt}, then says nothing. */
    static void silentRobot(String name, int port, long silentAt, Consumer<String> faults) {
        try (ObjectConnection c = ObjectConnection.client(new Socket(InetAddress.getLoopbackAddress(), port), 256,
                SimulationKeys.fromEnvironment())) {
            c.write(new RobotHello(name, robosim.devices.RobotTypes.properties("ArRobot")));
            c.flush();
            java.io.Externalizable welcome = c.answerChallenge(SimulationKeys.fromEnvironment(), "robot");
            if (!(welcome instanceof RobotWelcome w) || !w.isAccepted()) {
                faults.accept(name + " was refused");
                return;
            }
            for (long k = c.readStep(); k >= 0 && k < silentAt; k = c.readStep()) {
                c.write(new StepRequest(k, 0, 0, false, List.of()));
                c.flush();
                c.read(StepResponse.class);
            }
            // silent from here: the Environment's step timeout must drop us and close the connection
            c.setReadTimeoutMs(0);
            while (true) {
                c.readStep();
            }
        } catch (IOException expected) {
            // dropped, or the end
        }
    }

    /** A viewer that says hello with a small receive buffer and never reads again. */
    static Socket frozenViewer(int port) throws IOException {
        Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
        s.setReceiveBufferSize(4096);
        SimulationKeys secret = SimulationKeys.fromEnvironment();
        ObjectConnection c = ObjectConnection.client(s, 256, secret);
        c.write(new ViewerHello(false));
        c.flush();
        if (secret != null) { // prove it (and take the snapshot), then never read again
            c.answerChallenge(secret, "viewer");
        }
        return s; // never read again
    }

    /** Runs a command and returns what it printed (stdout and stderr). */
    static String run(String... cmd) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        p.waitFor();
        return out;
    }
}
