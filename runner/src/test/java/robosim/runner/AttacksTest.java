package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Settings;
import robosim.protocol.GeometryHello;
import robosim.protocol.ObjectConnection;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * A hostile client against the Environment's ports, over real sockets: each attack is refused or cut
 * off, and the simulation goes on. (A forged Geometry answer: FaultsTest; the control port:
 * ControlPortTest.)
 */
class AttacksTest {
    /** How long any wait for the Environment may take on a loaded machine, s. */
    private static final int LONG_S = 60;

    private static ClientWorkerCoordinator start(Settings.Builder settings) throws Exception {
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(
                new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml")), settings.build());
        env.start();
        return env;
    }

    private static Settings.Builder settings() {
        return Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).resetEvery(64)
                .handshakeTimeoutMs(LONG_S * 1000);
    }

    /** The three robots of three-robots.xml by hand: hello and welcome. */
    private static List<ObjectConnection> robots(int port) throws IOException {
        List<ObjectConnection> robots = new ArrayList<>();
        String[] names = {"r1", "r2", "r3"};
        RobotProperties[] types = {robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("Scout")};
        for (int i = 0; i < 3; i++) {
            ObjectConnection c = new ObjectConnection(socket(port), 64);
            c.write(new RobotHello(names[i], types[i]));
            c.flush();
            assertTrue(c.read(RobotWelcome.class).isAccepted());
            robots.add(c);
        }
        return robots;
    }

    /** Steps {@code from} .. {@code to - 1} with every robot standing still. */
    private static void step(List<ObjectConnection> robots, long from, long to) throws IOException {
        for (long k = from; k < to; k++) {
            for (ObjectConnection r : robots) {
                assertEquals(k, r.readStep());
                r.write(new StepRequest(k, 0, 0, false, List.of()));
                r.flush();
            }
            for (ObjectConnection r : robots) {
                assertEquals(k, r.read(StepResponse.class).step());
            }
        }
    }

    private static Socket socket(int port) throws IOException {
        Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
        s.setSoTimeout(LONG_S * 1000);
        return s;
    }

    /** True when the peer closes {@code s} (end of stream or reset) before the test's long timeout. */
    private static boolean closedByPeer(Socket s) throws IOException {
        InputStream in = s.getInputStream();
        try {
            while (in.read() >= 0) {
                // whatever it says before it closes
            }
            return true;
        } catch (SocketTimeoutException e) {
            return false;
        } catch (IOException reset) {
            return true;
        }
    }

    @Test
    void aSecondGeometryHelloWhileOneIsLiveIsRefusedAndTheRunGoesOn() throws Exception {
        try (ClientWorkerCoordinator env = start(settings().maxSteps(10))) {
            int[] ports = env.ports();
            Thread geometry = new Thread(() -> {
                try {
                    new robosim.geometry.GeometryClient(socket(ports[2]), 64).run();
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }, "test-geometry");
            geometry.start();
            List<ObjectConnection> robots = robots(ports[0]);
            step(robots, 0, 5);
            try (ObjectConnection intruder = new ObjectConnection(socket(ports[2]), 64)) {
                intruder.write(new GeometryHello());
                intruder.flush();
                SimulationEnd refusal = intruder.read(SimulationEnd.class);
                assertTrue(refusal.reason().contains("already attached"), refusal.reason());
            }
            step(robots, 5, 10);
            assertTrue(env.awaitEnd(LONG_S, TimeUnit.SECONDS));
            assertTrue(env.summary().completed(), env.summary().reason());
            assertEquals(0, env.summary().geometryLosses());
            assertEquals(0, env.summary().geometryAttaches(), "nobody took over");
            geometry.join(TimeUnit.SECONDS.toMillis(LONG_S));
            for (ObjectConnection r : robots) {
                r.close();
            }
        }
    }

    @Test
    void aGeometryProcessThatDiesWhileTheRunWaitsIsNoticedAndANewOneMayAttach() throws Exception {
        RunEvents events = new RunEvents();
        try (ClientWorkerCoordinator env = start(settings().maxSteps(10))) {
            env.listen(events);
            int[] ports = env.ports();
            Socket first = socket(ports[2]);
            Thread geometry = new Thread(() -> {
                try {
                    new robosim.geometry.GeometryClient(first, 64).run();
                } catch (IOException e) {
                    // closed under it below: expected
                }
            }, "test-geometry-1");
            geometry.start();
            List<ObjectConnection> robots = robots(ports[0]);
            step(robots, 0, 5);
            // the robots hold step 5 back, so the Environment waits and its Geometry worker is idle
            first.close();
            assertTrue(events.geometryLost.await(LONG_S, TimeUnit.SECONDS), "the idle worker noticed the loss");
            java.util.concurrent.CompletableFuture<String> second = java.util.concurrent.CompletableFuture.supplyAsync(() -> {
                try {
                    return new robosim.geometry.GeometryClient(socket(ports[2]), 64).run();
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            assertTrue(events.geometryAttached.await(LONG_S, TimeUnit.SECONDS), "a new Geometry process attached");
            step(robots, 5, 10);
            assertTrue(env.awaitEnd(LONG_S, TimeUnit.SECONDS));
            assertEquals(1, env.summary().geometryLosses());
            assertEquals(1, env.summary().geometryAttaches());
            String secondEnd = second.get(LONG_S, TimeUnit.SECONDS);
            assertFalse(secondEnd.startsWith("refused"), "the new one served to the end: " + secondEnd);
            for (ObjectConnection r : robots) {
                r.close();
            }
        }
    }

    @Test
    void aHandshakeTrickledInIsDroppedAtTheDeadline() throws Exception {
        try (ClientWorkerCoordinator env = start(settings().handshakeTimeoutMs(1000))) {
            try (Socket s = socket(env.ports()[0])) {
                // a valid stream header, one byte at a time, each well within any per-read timeout
                byte[] header = {(byte) 0xAC, (byte) 0xED, 0x00, 0x05, 0x73, 0x72};
                OutputStream out = s.getOutputStream();
                boolean closed = false;
                long giveUp = System.nanoTime() + TimeUnit.SECONDS.toNanos(LONG_S);
                for (int i = 0; !closed && System.nanoTime() < giveUp; i++) {
                    try {
                        out.write(header[Math.min(i, header.length - 1)]);
                        out.flush();
                    } catch (IOException reset) {
                        closed = true;
                    }
                    s.setSoTimeout(200);
                    try {
                        closed |= s.getInputStream().read() < 0;
                    } catch (SocketTimeoutException stillOpen) {
                        // the next byte
                    } catch (IOException reset) {
                        closed = true;
                    }
                }
                assertTrue(closed, "the trickling client was still held after " + LONG_S + " s");
            }
        }
    }

    @Test
    void aStrangerGetsAFewKilobytesNotTheMessageBudget() throws Exception {
        // a handshake deadline far beyond the test's wait: only the byte cap can close this connection in time
        try (ClientWorkerCoordinator env = start(settings().handshakeTimeoutMs(10 * LONG_S * 1000))) {
            try (Socket s = socket(env.ports()[1])) {
                // a stream header, then a string announced as 70 MB, of which 1 MB is sent
                ByteArrayOutputStream bytes = new ByteArrayOutputStream();
                bytes.writeBytes(new byte[] {(byte) 0xAC, (byte) 0xED, 0x00, 0x05, 0x7C});
                bytes.writeBytes(java.nio.ByteBuffer.allocate(8).putLong(70_000_000L).array());
                bytes.writeBytes(new byte[1 << 20]);
                try {
                    s.getOutputStream().write(bytes.toByteArray());
                    s.getOutputStream().flush();
                } catch (IOException reset) {
                    // cut off before all of it was taken: what the test wants
                }
                assertTrue(closedByPeer(s), "a stranger's 1 MB was taken: the pre-handshake cap did not hold");
            }
        }
    }

    @Test
    void connectionsOverThePortsCapAreClosedAtOnceAndTheRunStillGoesThrough() throws Exception {
        // a handshake deadline far beyond the test's wait: only the cap can close the fifth connection in time
        try (ClientWorkerCoordinator env = start(settings().maxConnections(4).inProcessGeometry(true).maxSteps(5)
                .handshakeTimeoutMs(10 * LONG_S * 1000))) {
            int[] ports = env.ports();
            List<Socket> silent = new ArrayList<>();
            for (int i = 0; i < 4; i++) {
                silent.add(socket(ports[1]));
            }
            try (Socket oneTooMany = socket(ports[1])) {
                assertTrue(closedByPeer(oneTooMany), "the fifth silent viewer connection was held");
            }
            for (Socket s : silent) {
                s.close();
            }
            List<ObjectConnection> robots = robots(ports[0]);
            step(robots, 0, 5);
            assertTrue(env.awaitEnd(LONG_S, TimeUnit.SECONDS));
            assertTrue(env.summary().completed(), env.summary().reason());
            for (ObjectConnection r : robots) {
                r.close();
            }
        }
    }

    @Test
    void aNameWithANewlineCannotForgeALogLine() throws Exception {
        PrintStream original = System.err;
        ByteArrayOutputStream captured = new ByteArrayOutputStream();
        String forged = "00:00:00.000 [main] ERROR Forged - the run failed";
        try (ClientWorkerCoordinator env = start(settings())) {
            System.setErr(new PrintStream(captured, true, StandardCharsets.UTF_8));
            try (ObjectConnection c = new ObjectConnection(socket(env.ports()[0]), 64)) {
                c.write(new RobotHello("evil\n" + forged, robosim.devices.RobotTypes.properties("ArRobot")));
                c.flush();
                RobotWelcome refusal = c.read(RobotWelcome.class);
                assertFalse(refusal.isAccepted());
            }
            // (the refusal is logged before it is sent: the line is there once the refusal is read)
        } finally {
            System.setErr(original);
        }
        String log = captured.toString(StandardCharsets.UTF_8);
        assertTrue(log.contains("evil?" + forged), "the name is logged, escaped: " + log);
        for (String line : log.split("\n")) {
            assertFalse(line.startsWith(forged), "a forged line: " + log);
        }
    }
}
