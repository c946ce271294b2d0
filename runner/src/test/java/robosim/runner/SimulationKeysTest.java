package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Settings;
import robosim.examples.BackAndForth;
import robosim.geometry.GeometryClient;
import robosim.devices.ArRobot;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.devices.Scout;
import robosim.protocol.Challenge;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Proof;
import robosim.protocol.ProtocolException;
import robosim.protocol.SimulationKeys;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * With a shared secret every client proves it by challenge and response: robots, viewers and Geometry
 * that know it take part; one without it, with a wrong one, or replaying another connection's proof is
 * refused, and the run goes on.
 */
class SimulationKeysTest {
    private static final int LONG_S = 60;

    private static SimulationKeys secret(String text) throws IOException {
        return SimulationKeys.of(text, "test");
    }

    private static Socket socket(int port) throws IOException {
        Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
        s.setSoTimeout(LONG_S * 1000);
        return s;
    }

    private static HardwareSimulator connect(String name, RobotType type, int port, SimulationKeys s) throws IOException {
        HardwareSimulator sim = new HardwareSimulator(name, type);
        sim.connect(socket(port), 64, s);
        return sim;
    }

    @Test
    void onlyClientsThatProveTheSecretTakePart() throws Exception {
        SimulationKeys right = secret("the right secret, 32 characters");
        Settings settings = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).keys(right)
                .maxSteps(20).resetEvery(64).handshakeTimeoutMs(LONG_S * 1000).build();
        try (ClientWorkerCoordinator env = new ClientWorkerCoordinator(
                new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml")), settings)) {
            env.start();
            int[] ports = env.ports();

            // no secret, a wrong one: refused, each with its reason
            ProtocolException none = assertThrows(ProtocolException.class,
                    () -> connect("r1", new ArRobot(), ports[0], null));
            assertTrue(none.getMessage().startsWith("the Environment asks for the shared secret"), none.getMessage());
            ProtocolException wrong = assertThrows(ProtocolException.class,
                    () -> connect("r1", new ArRobot(), ports[0], secret("a wrong secret, also long enough")));
            assertEquals("the Environment refused robot r1: it did not prove the shared secret", wrong.getMessage());
            ProtocolException shared = assertThrows(ProtocolException.class, () -> robosim.hardware.ManyRobots
                    .runOverOneConnection(List.of(new HardwareSimulator("r1", new ArRobot()),
                            new HardwareSimulator("r2", new ArRobot())), List.of(new BackAndForth(), new BackAndForth()),
                            socket(ports[0]), 64, secret("a wrong secret, also long enough")));
            assertEquals("the Environment refused every robot: r1: it did not prove the shared secret; r2: it did not "
                    + "prove the shared secret", shared.getMessage());
            ProtocolException geometry = assertThrows(ProtocolException.class,
                    () -> new GeometryClient(socket(ports[2]), 64, null).run());
            assertTrue(geometry.getMessage().startsWith("the Environment asks for the shared secret"));

            // a proof recorded on one connection does not open another (each challenge is fresh)
            byte[] recorded;
            try (ObjectConnection first = new ObjectConnection(socket(ports[1]), 64)) {
                first.write(new ViewerHello(true));
                first.flush();
                recorded = right.prove("viewer", first.read(Challenge.class).nonce());
            }
            try (ObjectConnection replay = new ObjectConnection(socket(ports[1]), 64)) {
                replay.write(new ViewerHello(true));
                replay.flush();
                replay.read(Challenge.class);
                replay.write(new Proof(recorded));
                replay.flush();
                assertEquals("it did not prove the shared secret", replay.read(SimulationEnd.class).reason());
            }
            // a robot's proof is no viewer's
            try (ObjectConnection asRobot = new ObjectConnection(socket(ports[1]), 64)) {
                asRobot.write(new ViewerHello(true));
                asRobot.flush();
                asRobot.write(new Proof(right.prove("robot", asRobot.read(Challenge.class).nonce())));
                asRobot.flush();
                assertEquals("it did not prove the shared secret", asRobot.read(SimulationEnd.class).reason());
            }

            // those that know it run the whole simulation
            runsTheWholeSimulation(env, ports, right);
        }
    }

    @Test
    void withTheKeyPairEveryConnectionIsTlsAndStrangersNeverGetIn(@TempDir Path dir) throws Exception {
        SimulationKeys keys = TestKeys.keys(dir, "keys");
        SimulationKeys others = TestKeys.keys(dir, "others");
        // strangers first, under a short handshake deadline
        Settings strict = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).keys(keys)
                .maxSteps(20).resetEvery(64).handshakeTimeoutMs(1000).build();
        try (ClientWorkerCoordinator env = new ClientWorkerCoordinator(
                new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml")), strict)) {
            env.start();
            int[] ports = env.ports();
            // no keys: its object stream is no TLS; it is told so at once, and never gets a byte of the protocol
            IOException plain = assertThrows(IOException.class, () -> connect("r1", new ArRobot(), ports[0], null));
            assertEquals("the Environment speaks TLS (tls=on): set ROBOSIM_KEYS to the simulation's keys",
                    plain.getMessage());
            assertThrows(IOException.class, () -> new GeometryClient(socket(ports[2]), 64, null).run());
            // the secret alone (right, but no key pair): no TLS, not let in either
            assertThrows(IOException.class, () -> connect("r1", new ArRobot(), ports[0], secret(
                    java.nio.file.Files.readString(dir.resolve("keys/secret")))));
            // another simulation's keys: refused at TLS, before a byte of the protocol
            ProtocolException other = assertThrows(ProtocolException.class,
                    () -> connect("r1", new ArRobot(), ports[0], others));
            assertTrue(other.getMessage().startsWith("TLS handshake with 127.0.0.1:" + ports[0] + " failed"),
                    other.getMessage());
            assertThrows(ProtocolException.class, () -> ViewerClient.connect("127.0.0.1", ports[1],
                    new ViewerHello(true), LONG_S * 1000L, others));
            assertTrue(env.status().connected().isEmpty(), "nobody got in: " + env.status().connected());
        }
        Settings settings = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).keys(keys)
                .maxSteps(20).resetEvery(64).handshakeTimeoutMs(LONG_S * 1000).build();
        try (ClientWorkerCoordinator env = new ClientWorkerCoordinator(
                new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml")), settings)) {
            env.start();
            int[] ports = env.ports();
            // those with the keys run the whole simulation over TLS
            runsTheWholeSimulation(env, ports, keys);
        }
    }

    /** A viewer, Geometry and robots r1..r3 holding {@code keys} run the simulation to its end. */
    private static void runsTheWholeSimulation(ClientWorkerCoordinator env, int[] ports, SimulationKeys right)
            throws Exception {
        CompletableFuture<WorldSnapshot> seen = new CompletableFuture<>();
        ViewerClient viewer = ViewerClient.connect("127.0.0.1", ports[1], new ViewerHello(true), LONG_S * 1000L,
                right);
        viewer.start(new ViewerClient.Listener() {
            @Override
            public void snapshot(WorldSnapshot snapshot) {
                seen.complete(snapshot);
            }

            @Override
            public void update(robosim.protocol.PoseUpdate update) {
            }
        });
        CompletableFuture<String> g = CompletableFuture.supplyAsync(() -> {
            try {
                return new GeometryClient(socket(ports[2]), 64, right).run();
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
        HardwareSimulator r1 = connect("r1", new ArRobot(), ports[0], right); // (a socket of its own)
        CompletableFuture<String> first = CompletableFuture.supplyAsync(() -> {
            try {
                return r1.run(new BackAndForth());
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
        List<HardwareSimulator> shared = List.of(new HardwareSimulator("r2", new ArRobot()),
                new HardwareSimulator("r3", new Scout())); // (one shared connection)
        CompletableFuture<Void> others = CompletableFuture.runAsync(() -> {
            try {
                robosim.hardware.ManyRobots.runOverOneConnection(shared, List.of(new BackAndForth(), new BackAndForth()),
                        socket(ports[0]), 64, right);
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
        assertEquals("completed 20 steps", first.get(LONG_S, TimeUnit.SECONDS));
        others.get(LONG_S, TimeUnit.SECONDS);
        for (HardwareSimulator sim : shared) {
            assertEquals("completed 20 steps", sim.endReason());
        }
        g.get(LONG_S, TimeUnit.SECONDS);
        assertEquals(3, seen.get(LONG_S, TimeUnit.SECONDS).robotNames().size());
        assertEquals("completed 20 steps", viewer.awaitEnd(LONG_S, TimeUnit.SECONDS).reason());
        assertTrue(env.summary().completed(), env.summary().reason());
    }
}
