package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
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
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;
import robosim.remote.RobotLink;

/**
 * The remote-control link over real sockets: RobotInfo.xml names each robot's port, the robot's
 * RemoteControlRobot listens there, and a command moves it by the expected distance in the expected
 * steps. Garbage gets an error or a closed link; the robot goes on obeying.
 */
class RemoteControlTest {
    private static final long LONG = 60;

    @Test
    void aForwardCommandMovesTheRobotByItsDistanceInTheExpectedSteps(@TempDir Path dir) throws Exception {
        int port1 = freePort();
        int port2 = freePort();
        Path info = dir.resolve("RobotInfo.xml");
        Files.writeString(info, "<robotInfo>\n  <robot name=\"rc1\" host=\"127.0.0.1\" port=\"" + port1 + "\"/>\n"
                + "  <robot name=\"rc2\" host=\"127.0.0.1\" port=\"" + port2 + "\"/>\n</robotInfo>\n");
        System.setProperty(RobotInfo.PROPERTY, info.toString());
        WorldSpec spec = new EnvironmentLoader().load(InJvmSimulation.env("remote.xml"));
        try (ClientWorkerCoordinator env = new ClientWorkerCoordinator(spec, Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true).maxSteps(0)
                .resetEvery(64).handshakeTimeoutMs(10_000).build())) {
            env.start();
            int[] ports = env.ports();
            List<PoseUpdate> seen = new CopyOnWriteArrayList<>();
            java.util.concurrent.CountDownLatch firstStep = new java.util.concurrent.CountDownLatch(1);
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", ports[1], true, 10_000);
            viewer.start(new ViewerClient.Listener() {
                @Override
                public void snapshot(WorldSnapshot snapshot) {
                }

                @Override
                public void update(PoseUpdate update) {
                    seen.add(update);
                    firstStep.countDown();
                    synchronized (seen) {
                        seen.notifyAll();
                    }
                }
            });
            startRemoteControlRobots(spec, ports[0]);
            BlockingQueue<String> replies = new LinkedBlockingQueue<>();
            RobotInfo rc1 = RobotInfo.load(info).get(0);
            // a robot sends its first request only once its control code has started, and so its listener:
            // after the first step every link is up
            assertTrue(firstStep.await(LONG, TimeUnit.SECONDS));
            try (RobotLink link = new RobotLink(rc1, replies::add, null)) {
                assertTrue(link.ensureConnected(), "rc1 listens on its RobotInfo port");
                assertTrue(link.send("forward 750"));
                String done = replies.poll(LONG, TimeUnit.SECONDS);
                assertNotNull(done, "no reply to forward 750");
                assertTrue(done.startsWith("done forward 750 x=2750.0 y=2000.0 heading=0.0"), done);
                // the viewer's record: x went 2000 -> 2750 in exactly 3 steps of 250 mm (500 ms steps at 500 mm/s)
                long first = firstStepAt(seen, 2750);
                double[] xs = new double[5];
                for (int i = 0; i < 5; i++) {
                    xs[i] = at(seen, first - 3 + i).xMm(0);
                }
                assertEquals(2000, xs[0], 1e-9, "before");
                assertEquals(2250, xs[1], 1e-9);
                assertEquals(2500, xs[2], 1e-9);
                assertEquals(2750, xs[3], 1e-9, "after three steps");
                assertEquals(2750, xs[4], 1e-9, "and then it stands");

                // garbage: an error line, and the robot still obeys
                assertTrue(link.send("jump 3 m high"));
                assertTrue(replies.poll(LONG, TimeUnit.SECONDS).startsWith("error not a command"));
                assertTrue(link.send("forward NaN"));
                assertTrue(replies.poll(LONG, TimeUnit.SECONDS).startsWith("error not a command"));
            }
            // a line far too long closes that link with an error; a new link works
            try (Socket raw = new Socket(InetAddress.getLoopbackAddress(), port1)) {
                raw.setSoTimeout((int) TimeUnit.SECONDS.toMillis(LONG));
                OutputStream out = raw.getOutputStream();
                out.write(new byte[RemoteControlRobot.MAX_LINE * 4]);
                out.flush();
                BufferedReader in = new BufferedReader(new InputStreamReader(raw.getInputStream(), StandardCharsets.UTF_8));
                String line = in.readLine();
                assertTrue(line != null && line.startsWith("error line longer than"), line);
            }
            try (RobotLink link = new RobotLink(rc1, replies::add, null)) {
                assertTrue(link.ensureConnected());
                assertTrue(link.send("left 90"));
                String done = replies.poll(LONG, TimeUnit.SECONDS);
                assertTrue(done != null && done.startsWith("done left 90 x=2750.0 y=2000.0 heading=90.0"), done);
            }
            assertTrue(env.status().left().isEmpty(), "both robots still in the simulation");
        } finally {
            System.clearProperty(RobotInfo.PROPERTY);
        }
    }

    @Test
    void theRemoteControlDrivesAFootBotOfArgosManualControl(@TempDir Path dir) throws Exception {
        // examples/argos/manualcontrol.xml: ten foot-bots, each a RemoteControlRobot on the port a RobotInfo file gives
        WorldSpec spec = new EnvironmentLoader().load(Path.of("..", "examples", "argos", "manualcontrol.xml"));
        StringBuilder robots = new StringBuilder("<robotInfo>\n");
        for (WorldSpec.RobotSpec r : spec.robots()) {
            robots.append("  <robot name=\"").append(r.name()).append("\" host=\"127.0.0.1\" port=\"").append(freePort())
                    .append("\"/>\n");
        }
        Path info = Files.writeString(dir.resolve("manualcontrol-robots.xml"), robots + "</robotInfo>\n");
        System.setProperty(RobotInfo.PROPERTY, info.toString());
        try (ClientWorkerCoordinator env = new ClientWorkerCoordinator(spec, Settings.builder().ports(
                InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true).maxSteps(0).resetEvery(64)
                .handshakeTimeoutMs(10_000).build())) {
            env.start();
            int[] ports = env.ports();
            java.util.concurrent.CountDownLatch firstStep = new java.util.concurrent.CountDownLatch(1);
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
            startRemoteControlRobots(spec, ports[0]);
            assertTrue(firstStep.await(LONG, TimeUnit.SECONDS));
            RobotInfo chosen = RobotInfo.load(info).get(3); // (the one chosen in the Remote Control's window)
            WorldSpec.RobotSpec start = spec.robots().get(3);
            BlockingQueue<String> replies = new LinkedBlockingQueue<>();
            try (RobotLink link = new RobotLink(chosen, replies::add, null)) {
                assertTrue(link.ensureConnected(), chosen.name() + " listens on its port");
                assertTrue(link.send("left 90"));
                String turned = replies.poll(LONG, TimeUnit.SECONDS);
                double heading = (start.headingDeg() + 90) % 360;
                assertTrue(turned != null && turned.startsWith("done left 90 x=") && turned.endsWith(
                        String.format(java.util.Locale.ROOT, " heading=%.1f", heading)), turned + ", from "
                        + start.headingDeg());
                assertTrue(link.send("forward 100"));
                String moved = replies.poll(LONG, TimeUnit.SECONDS);
                assertNotNull(moved, "no reply to forward 100");
                java.util.regex.Matcher at = java.util.regex.Pattern.compile("x=([-0-9.]+) y=([-0-9.]+)").matcher(moved);
                assertTrue(moved.startsWith("done forward 100 ") && at.find(), moved);
                double gone = Math.hypot(Double.parseDouble(at.group(1)) - start.xMm(),
                        Double.parseDouble(at.group(2)) - start.yMm());
                assertTrue(gone > 0 && gone <= 100.5, "it drove ahead, 100 mm at most (less where it touched): " + moved
                        + " from (" + start.xMm() + ", " + start.yMm() + ")");
            }
            assertTrue(env.status().left().isEmpty(), "every foot-bot still in the simulation");
        } finally {
            System.clearProperty(RobotInfo.PROPERTY);
        }
    }

    @Test
    void aBadRobotInfoFileIsReportedInOneLine(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.xml");
        Files.writeString(bad, "<robotInfo><robot name=\"a\" port=\"eighty\"/></robotInfo>");
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> RobotInfo.load(bad));
        assertEquals(bad + ": robot a: port \"eighty\" is not a number", e.getMessage());
        Files.writeString(bad, "<robotInfo><robot name=\"a\" port=\"70000\"/></robotInfo>");
        assertEquals(bad + ": robot a: port 70000 is not between 1 and 65535",
                org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> RobotInfo.load(bad))
                        .getMessage());
        assertEquals(2, RobotInfo.load(InJvmSimulation.env("RobotInfo.xml")).size());
    }

    /** The first step at which robot 0 is at x, once the step after it has been seen too. */
    private static long firstStepAt(List<PoseUpdate> seen, double x) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(LONG);
        synchronized (seen) {
            while (true) {
                for (PoseUpdate u : seen) {
                    if (Math.abs(u.xMm(0) - x) < 1e-9 && at(seen, u.step() + 1) != null) {
                        return u.step();
                    }
                }
                long left = deadline - System.nanoTime();
                assertTrue(left > 0, "the viewer never saw x = " + x);
                seen.wait(TimeUnit.NANOSECONDS.toMillis(left) + 1);
            }
        }
    }

    private static PoseUpdate at(List<PoseUpdate> seen, long step) {
        for (PoseUpdate u : seen) {
            if (u.step() == step) {
                return u;
            }
        }
        return null;
    }

    /** Each robot of {@code spec} a RemoteControlRobot, in a Hardware Simulator of its own on the robot port. */
    private static void startRemoteControlRobots(WorldSpec spec, int robotPort) throws Exception {
        for (WorldSpec.RobotSpec r : spec.robots()) {
            HardwareSimulator sim = new HardwareSimulator(r.name(), robosim.devices.RobotTypes.byName(r.type()));
            sim.connect(new Socket(InetAddress.getLoopbackAddress(), robotPort), 64);
            CompletableFuture.runAsync(() -> {
                try {
                    sim.run(new RemoteControlRobot());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
        }
    }

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }
}
