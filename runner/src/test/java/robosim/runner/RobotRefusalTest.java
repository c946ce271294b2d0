package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Settings;
import robosim.examples.BackAndForth;
import robosim.devices.ArRobot;
import robosim.hardware.HardwareSimulator;
import robosim.protocol.ProtocolException;

/** Unknown, duplicate and mistyped robots are refused with a reason; the Environment keeps waiting. */
class RobotRefusalTest {
    @Test
    void refusedRobotsDoNotStopTheSimulationFromStarting() throws Exception {
        var spec = new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml"));
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(spec, Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true).maxSteps(20)
                .resetEvery(64).handshakeTimeoutMs(10_000).build());
        env.start();
        int port = env.ports()[0];
        try {
            assertEquals("the Environment refused robot ghost: no robot named \"ghost\" in "
                    + "src/test/resources/three-robots.xml (robots: r1, r2, r3)", refusal("ghost", new ArRobot(), port));
            assertEquals("the Environment refused robot r3: robot r3 is a Scout in "
                    + "src/test/resources/three-robots.xml, but says it is an ArRobot (robot.sh: give --type Scout, or "
                    + "leave --type out to take the file's)", refusal("r3", new ArRobot(), port));

            HardwareSimulator r1 = connect("r1", new ArRobot(), port);
            assertEquals("the Environment refused robot r1: robot r1 is already connected",
                    refusal("r1", new ArRobot(), port));
            HardwareSimulator r2 = connect("r2", new ArRobot(), port);
            // of any type (robot.sh without --type): it takes the file's, a Scout, with the Scout's 16 sonars
            HardwareSimulator r3 = connect("r3", null, port);
            CompletableFuture<String> a = CompletableFuture.supplyAsync(() -> run(r1), TestThreads.ROBOTS);
            CompletableFuture<String> b = CompletableFuture.supplyAsync(() -> run(r2), TestThreads.ROBOTS);
            CompletableFuture<Integer> sonars = new CompletableFuture<>();
            CompletableFuture<String> c = CompletableFuture.supplyAsync(() -> {
                try {
                    return r3.run(robot -> {
                        sonars.complete(robot.sonarAnglesDeg().length);
                        new BackAndForth().run(robot);
                    });
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            assertEquals("completed 20 steps", a.get(60, TimeUnit.SECONDS));
            assertEquals("completed 20 steps", b.get(60, TimeUnit.SECONDS));
            assertEquals("completed 20 steps", c.get(60, TimeUnit.SECONDS));
            assertEquals(16, sonars.get(60, TimeUnit.SECONDS));
            assertTrue(env.summary().completed());
        } finally {
            env.close();
        }
    }

    private static HardwareSimulator connect(String name, robosim.devices.RobotType type, int port) throws Exception {
        HardwareSimulator sim = new HardwareSimulator(name, type);
        sim.connect(new Socket(InetAddress.getLoopbackAddress(), port), 64);
        return sim;
    }

    private static String refusal(String name, robosim.devices.RobotType type, int port) {
        return assertThrows(ProtocolException.class, () -> connect(name, type, port)).getMessage();
    }

    private static String run(HardwareSimulator sim) {
        try {
            return sim.run(new BackAndForth());
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }
}
