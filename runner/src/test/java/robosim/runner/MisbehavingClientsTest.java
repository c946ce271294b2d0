package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Settings;
import robosim.examples.BackAndForth;
import robosim.devices.ArRobot;
import robosim.hardware.HardwareSimulator;
import robosim.devices.Scout;
import robosim.protocol.GeometryHello;
import robosim.protocol.ObjectConnection;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.StepRequest;

/** Clients that leave early, speak out of turn or hang: the Environment copes and stays stoppable. */
class MisbehavingClientsTest {
    private static WorldSpec spec() throws Exception {
        return new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml"));
    }

    private static ClientWorkerCoordinator start(boolean inProcessGeometry, long steps) throws Exception {
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(spec(), Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(inProcessGeometry).maxSteps(steps)
                .resetEvery(64).handshakeTimeoutMs(10_000).build());
        env.start();
        return env;
    }

    private static HardwareSimulator connect(String name, robosim.devices.RobotType type, int port) throws Exception {
        HardwareSimulator sim = new HardwareSimulator(name, type);
        sim.connect(new Socket(InetAddress.getLoopbackAddress(), port), 64);
        return sim;
    }

    private static CompletableFuture<String> run(HardwareSimulator sim) {
        return CompletableFuture.supplyAsync(() -> {
            try {
                return sim.run(new BackAndForth());
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
    }

    /** A raw robot client: says hello as {@code name} and reads its welcome. */
    private static ObjectConnection raw(String name, int port) throws IOException {
        ObjectConnection c = new ObjectConnection(new Socket(InetAddress.getLoopbackAddress(), port), 64);
        c.write(new RobotHello(name, robosim.devices.RobotTypes.properties("ArRobot")));
        c.flush();
        assertTrue(c.read(RobotWelcome.class).isAccepted());
        return c;
    }

    @Test
    void aRobotThatLeavesBeforeTheStartFreesItsNameForAReconnect() throws Exception {
        try (ClientWorkerCoordinator env = start(true, 10)) {
            int port = env.ports()[0];
            raw("r1", port).close();
            // the Environment notices the close on its own; until then the name is still taken
            HardwareSimulator r1 = null;
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (r1 == null) {
                try {
                    r1 = connect("r1", new ArRobot(), port);
                } catch (ProtocolException stillTaken) {
                    assertTrue(stillTaken.getMessage().endsWith("robot r1 is already connected"), stillTaken.getMessage());
                    assertTrue(System.nanoTime() < deadline, "the departure was never noticed");
                }
            }
            CompletableFuture<String> a = run(r1);
            CompletableFuture<String> b = run(connect("r2", new ArRobot(), port));
            CompletableFuture<String> c = run(connect("r3", new Scout(), port));
            assertEquals("completed 10 steps", a.get(60, TimeUnit.SECONDS));
            assertEquals("completed 10 steps", b.get(60, TimeUnit.SECONDS));
            assertEquals("completed 10 steps", c.get(60, TimeUnit.SECONDS));
        }
    }

    @Test
    void aRobotSpeakingOutOfTurnIsDroppedAloneAndTheOthersFinish() throws Exception {
        try (ClientWorkerCoordinator env = start(true, 30)) {
            int port = env.ports()[0];
            ObjectConnection bad = raw("r1", port);
            CompletableFuture<String> b = run(connect("r2", new ArRobot(), port));
            CompletableFuture<String> c = run(connect("r3", new Scout(), port));
            assertEquals(0, bad.readStep());
            bad.write(new StepRequest(7, 0, 0, false, List.of()));
            bad.flush();
            assertEquals("completed 30 steps", b.get(60, TimeUnit.SECONDS));
            assertEquals("completed 30 steps", c.get(60, TimeUnit.SECONDS));
            assertTrue(env.summary().completed());
            bad.close();
        }
    }

    @Test
    void stopReturnsEvenWhileGeometryHangsInTheMiddleOfAStep() throws Exception {
        ClientWorkerCoordinator env = start(false, 0);
        int[] ports = env.ports();
        // a Geometry process that attaches and then never answers
        ObjectConnection geometry = new ObjectConnection(new Socket(InetAddress.getLoopbackAddress(), ports[2]), 64);
        geometry.write(new GeometryHello());
        geometry.flush();
        List<CompletableFuture<String>> robots = List.of(run(connect("r1", new ArRobot(), ports[0])),
                run(connect("r2", new ArRobot(), ports[0])), run(connect("r3", new Scout(), ports[0])));
        geometry.read(robosim.protocol.GeometryWorld.class);
        geometry.read(robosim.protocol.GeometryStepRequest.class); // step 0 is now waiting for us
        CompletableFuture<Void> stopping = CompletableFuture.runAsync(() -> env.stop("stopped by the test"), TestThreads.ROBOTS);
        stopping.get(30, TimeUnit.SECONDS);
        assertFalse(env.summary().completed());
        // the stuck step holds the robots' responses, so stop closes their connections: each robot ends,
        // told the end or finding its connection closed (a reset, when the close crossed its own traffic)
        for (CompletableFuture<String> r : robots) {
            try {
                r.get(30, TimeUnit.SECONDS);
            } catch (java.util.concurrent.ExecutionException e) {
                Throwable cause = e.getCause().getCause();
                assertTrue(cause instanceof java.io.IOException, "the robot ended with its connection closed, not "
                        + cause);
            }
        }
        env.close();
        geometry.close();
    }
}
