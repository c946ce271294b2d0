package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Settings;
import robosim.examples.RemoteControlRobot;
import robosim.examples.RobotInfo;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.protocol.PoseUpdate;
import robosim.protocol.SimulationKeys;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;
import robosim.remote.RobotLink;

/**
 * With the simulation's keys a remote-control robot's link speaks TLS and takes commands only after the
 * shared secret's proof: the Remote Control's link with the keys drives the robot; one without them,
 * with another simulation's, or over TLS without the proof gets nowhere.
 */
class RemoteControlKeysTest {
    private static final long LONG = 60;

    @Test
    void withKeysTheLinkIsTlsAndTakesCommandsOnlyAfterTheProof(@TempDir Path dir) throws Exception {
        SimulationKeys keys = TestKeys.keys(dir, "keys");
        SimulationKeys others = TestKeys.keys(dir, "others");
        int port1;
        int port2;
        try (ServerSocket a = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
                ServerSocket b = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port1 = a.getLocalPort();
            port2 = b.getLocalPort();
        }
        Path info = dir.resolve("RobotInfo.xml");
        Files.writeString(info, "<robotInfo>\n  <robot name=\"rc1\" host=\"127.0.0.1\" port=\"" + port1 + "\"/>\n"
                + "  <robot name=\"rc2\" host=\"127.0.0.1\" port=\"" + port2 + "\"/>\n</robotInfo>\n");
        System.setProperty(RobotInfo.PROPERTY, info.toString());
        WorldSpec spec = new EnvironmentLoader().load(InJvmSimulation.env("remote.xml"));
        try (ClientWorkerCoordinator env = new ClientWorkerCoordinator(spec, Settings.builder()
                .ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true).maxSteps(0)
                .resetEvery(64).handshakeTimeoutMs(10_000).build())) {
            env.start();
            int[] ports = env.ports();
            CountDownLatch firstStep = new CountDownLatch(1);
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", ports[1], true, 10_000);
            viewer.start(new ViewerClient.Listener() {
                @Override
                public void snapshot(WorldSnapshot snapshot) {
                }

                @Override
                public void update(PoseUpdate update) {
                    firstStep.countDown();
                }
            });
            for (WorldSpec.RobotSpec r : spec.robots()) {
                HardwareSimulator sim = new HardwareSimulator(r.name(), robosim.devices.RobotTypes.byName(r.type()));
                sim.connect(new Socket(InetAddress.getLoopbackAddress(), ports[0]), 64);
                CompletableFuture.runAsync(() -> {
                    try {
                        sim.run(new RemoteControlRobot(keys));
                    } catch (Exception e) {
                        throw new IllegalStateException(e);
                    }
                }, TestThreads.ROBOTS);
            }
            // each robot's link is up once its control code runs, so after the first step
            assertTrue(firstStep.await(LONG, TimeUnit.SECONDS));
            RobotInfo rc1 = RobotInfo.load(info).get(0);

            BlockingQueue<String> replies = new LinkedBlockingQueue<>();
            try (RobotLink link = new RobotLink(rc1, replies::add, keys)) {
                assertTrue(link.ensureConnected(), "the link with the keys proves the secret over TLS");
                assertTrue(link.send("forward 250"));
                String done = replies.poll(LONG, TimeUnit.SECONDS);
                assertTrue(done != null && done.startsWith("done forward 250 x=2250.0"), done);
            }
            try (RobotLink stranger = new RobotLink(rc1, replies::add, others)) {
                assertFalse(stranger.ensureConnected(), "another simulation's key pair is refused");
                String why = replies.poll(LONG, TimeUnit.SECONDS);
                assertTrue(why != null && why.contains("TLS handshake with 127.0.0.1:" + port1 + " failed"), why);
            }
            // plain text to the TLS link: closed, never obeyed
            try (Socket plain = new Socket(InetAddress.getLoopbackAddress(), port1)) {
                plain.setSoTimeout((int) TimeUnit.SECONDS.toMillis(LONG));
                plain.getOutputStream().write("forward 250\n".getBytes(StandardCharsets.UTF_8));
                plain.getOutputStream().flush();
                assertTrue(endsWithoutALine(plain), "a plain-text link is closed without an answer");
            }
            // TLS with the key pair but no proof: every command is refused until the proof
            try (Socket raw = new Socket(InetAddress.getLoopbackAddress(), port1); Socket tls = keys.tls().client(raw)) {
                raw.setSoTimeout((int) TimeUnit.SECONDS.toMillis(LONG));
                BufferedReader in = new BufferedReader(new InputStreamReader(tls.getInputStream(), StandardCharsets.UTF_8));
                OutputStream out = tls.getOutputStream();
                out.write("forward 250\nprove 00\n".getBytes(StandardCharsets.UTF_8));
                out.flush();
                String refused = in.readLine();
                assertNotNull(refused);
                assertTrue(refused.startsWith("error prove the shared secret first"), refused);
                String wrong = in.readLine();
                assertTrue(wrong != null && wrong.startsWith("error that is not the proof"), wrong);
            }
        } finally {
            System.clearProperty(RobotInfo.PROPERTY);
        }
    }

    /** True if the peer closes (or resets) the connection before sending a whole line. */
    private static boolean endsWithoutALine(Socket s) throws IOException {
        try {
            return new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8)).readLine() == null;
        } catch (java.net.SocketException reset) {
            return true;
        }
    }
}
