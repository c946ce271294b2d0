package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Departure;
import robosim.environment.run.RobotLoss;
import robosim.environment.run.RunListener;
import robosim.environment.run.RunSummary;
import robosim.environment.run.Settings;
import robosim.protocol.Protocol;
import robosim.protocol.SharedReplies;
import robosim.protocol.SharedRequests;
import robosim.protocol.StepRequest;

/**
 * The shared connection's bad input: a frame naming a robot not on the connection, one with more requests
 * than the connection has robots, one naming a robot twice, one cut short. Each drops that connection (its
 * robots leave, with the reason) while the other robots go on to the end; and each robot of a shared
 * hello is welcomed or refused on its own. r1 and r2 share a connection by hand, r3 has its own.
 */
class SharedConnectionTest {
    private static final long LONG = 60;
    private static final int STEPS = 50;

    private static ClientWorkerCoordinator start() throws Exception {
        return start(RobotLoss.REMOVE);
    }

    private static ClientWorkerCoordinator start(RobotLoss loss) throws Exception {
        return start(Settings.builder().onRobotLoss(loss));
    }

    private static ClientWorkerCoordinator start(Settings.Builder b) throws Exception {
        Settings s = b.ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true).maxSteps(STEPS)
                .resetEvery(64).build();
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(
                new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml")), s);
        env.start();
        return env;
    }

    private static CompletableFuture<Void> standStill(String name, int port) {
        return CompletableFuture.runAsync(() -> {
            try (RawRobot r = new RawRobot(name, name.equals("r3") ? robosim.devices.RobotTypes.properties("Scout") : robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertTrue(r.welcome.isAccepted(), r.welcome.reason());
                while (r.next()) {
                    r.step(0, 0, false, List.of());
                }
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
    }

    private static StepRequest stand(long step) {
        return new StepRequest(step, 0, 0, false, List.of());
    }

    enum BadFrame {
        NOT_ON_THE_CONNECTION("sent a request for robot slot 7, which is not a robot of this connection"),
        TOO_MANY("sent 3 requests in one frame on a connection of 2 robot(s)"),
        TWICE("sent two requests for robot r1 in one frame"),
        TRUNCATED("bytes into a SharedRequests (a truncated message)");

        final String why;

        BadFrame(String why) {
            this.why = why;
        }

        SharedRequests frame() {
            SharedRequests f = new SharedRequests();
            f.add(0, stand(0));
            switch (this) {
                case NOT_ON_THE_CONNECTION -> f.add(7, stand(0));
                case TOO_MANY -> {
                    f.add(1, stand(0));
                    f.add(0, stand(0));
                }
                case TWICE -> f.add(0, stand(0));
                case TRUNCATED -> f.add(1, stand(0));
            }
            return f;
        }
    }

    @ParameterizedTest
    @EnumSource(BadFrame.class)
    void aBadFrameDropsItsConnectionAndTheOtherRobotsGoOn(BadFrame bad) throws Exception {
        ClientWorkerCoordinator env = start();
        try {
            int port = env.ports()[0];
            CompletableFuture<Void> r3 = standStill("r3", port);
            try (RawSharedRobots shared = new RawSharedRobots(port, List.of("r1", "r2"), robosim.devices.RobotTypes.properties("ArRobot"))) {
                assertEquals(2, shared.welcomes.count());
                for (int i = 0; i < 2; i++) {
                    assertEquals(i, shared.welcomes.slot(i));
                    assertTrue(shared.welcomes.welcome(i).isAccepted(), shared.welcomes.welcome(i).reason());
                }
                int given = 0;
                while (given < 2) { // (step 0 for both: in one frame, or after a frame of its own)
                    SharedReplies f = shared.next();
                    for (int i = 0; i < f.count(); i++) {
                        assertEquals(SharedReplies.Kind.STEP, f.kind(i));
                        assertEquals(0, f.step(i));
                        given++;
                    }
                }
                if (bad == BadFrame.TRUNCATED) {
                    shared.sendTruncated(bad.frame());
                } else {
                    shared.send(bad.frame());
                    assertTrue(endOfStream(shared), "the Environment closes the connection");
                }
            }
            r3.get(LONG, TimeUnit.SECONDS);
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            RunSummary summary = env.summary();
            assertTrue(summary.completed(), summary.reason());
            assertEquals(STEPS, summary.steps());
            List<Departure> gone = summary.departures();
            assertEquals(List.of("r1", "r2"), gone.stream().map(Departure::robot).sorted().toList());
            for (Departure d : gone) {
                assertTrue(d.why().contains(bad.why), d.robot() + ": " + d.why());
                assertEquals(0, d.step());
            }
        } finally {
            env.close();
        }
    }

    private static boolean endOfStream(RawSharedRobots shared) throws Exception {
        try {
            shared.next();
            return false;
        } catch (java.io.EOFException | java.net.SocketException e) {
            return true;
        }
    }

    @Test
    void eachRobotOfASharedHelloIsWelcomedOrRefusedAloneAndTheWelcomedOnesRun() throws Exception {
        ClientWorkerCoordinator env = start();
        try {
            int port = env.ports()[0];
            CompletableFuture<Void> r2 = standStill("r2", port);
            CompletableFuture<Void> r3 = standStill("r3", port);
            long last = -1;
            try (RawSharedRobots shared = new RawSharedRobots(port, List.of("ghost", "r1"), robosim.devices.RobotTypes.properties("ArRobot"))) {
                assertEquals(2, shared.welcomes.count());
                assertFalse(shared.welcomes.welcome(0).isAccepted());
                assertTrue(shared.welcomes.welcome(0).reason().startsWith("no robot named \"ghost\" in"),
                        shared.welcomes.welcome(0).reason());
                assertTrue(shared.welcomes.welcome(1).isAccepted(), shared.welcomes.welcome(1).reason());
                String end = null;
                while (end == null) {
                    SharedReplies f = shared.next();
                    SharedRequests requests = new SharedRequests();
                    for (int i = 0; i < f.count(); i++) {
                        assertEquals(1, f.slot(i), "only r1 is on this connection");
                        switch (f.kind(i)) {
                            case STEP -> requests.add(1, stand(f.step(i)));
                            case RESPONSE -> {
                                last = f.response(i).step();
                                if (f.step(i) != Protocol.END_OF_SIMULATION) {
                                    requests.add(1, stand(f.step(i)));
                                }
                            }
                            case END -> end = f.end(i).reason();
                            case WELCOME -> throw new AssertionError("a second welcome");
                        }
                    }
                    if (requests.count() > 0) {
                        shared.send(requests);
                    }
                }
                assertEquals("completed " + STEPS + " steps", end);
            }
            assertEquals(STEPS - 1, last);
            r2.get(LONG, TimeUnit.SECONDS);
            r3.get(LONG, TimeUnit.SECONDS);
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            assertTrue(env.summary().completed(), env.summary().reason());
            assertEquals(List.of(), env.summary().departures());
        } finally {
            env.close();
        }
    }

    /**
     * Robots of a shared connection that is lost are held, and a new process's shared connection takes them
     * over mid-run: their welcomes and their first step come in one frame (the world was waiting for r3's
     * request at the time), and the Hardware Simulators run them to the end.
     */
    @Test
    void robotsHeldFromALostSharedConnectionAreTakenOverByANewOne() throws Exception {
        ClientWorkerCoordinator env = start(RobotLoss.HOLD);
        try {
            int port = env.ports()[0];
            java.util.concurrent.CountDownLatch held = new java.util.concurrent.CountDownLatch(2);
            java.util.concurrent.CountDownLatch back = new java.util.concurrent.CountDownLatch(2);
            env.listen(new RunListener() {
                @Override
                public void robotHeld(String robot, long step, String why) {
                    held.countDown();
                }

                @Override
                public void robotReturned(String robot, long step) {
                    back.countDown();
                }
            });
            java.util.concurrent.CountDownLatch atTen = new java.util.concurrent.CountDownLatch(1);
            CompletableFuture<Void> r3 = CompletableFuture.runAsync(() -> {
                try (RawRobot r = new RawRobot("r3", robosim.devices.RobotTypes.properties("Scout"), port)) {
                    while (r.next()) {
                        if (r.step == 10) {
                            atTen.countDown(); // (the world collects step 10 until r1 and r2 are back)
                            if (!back.await(LONG, TimeUnit.SECONDS)) {
                                throw new AssertionError("r1 and r2 did not come back");
                            }
                        }
                        r.step(0, 0, false, List.of());
                    }
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            try (RawSharedRobots first = new RawSharedRobots(port, List.of("r1", "r2"), robosim.devices.RobotTypes.properties("ArRobot"))) {
                long[] due = {-1, -1};
                while (due[0] < 5 || due[1] < 5) { // (steps 0 to 4 taken, then the connection is lost)
                    SharedReplies f = first.next();
                    SharedRequests requests = new SharedRequests();
                    for (int i = 0; i < f.count(); i++) {
                        if (f.kind(i) == SharedReplies.Kind.STEP || f.kind(i) == SharedReplies.Kind.RESPONSE) {
                            due[f.slot(i)] = f.step(i);
                            if (f.step(i) < 5) {
                                requests.add(f.slot(i), stand(f.step(i)));
                            }
                        }
                    }
                    if (requests.count() > 0) {
                        first.send(requests);
                    }
                }
            }
            assertTrue(held.await(LONG, TimeUnit.SECONDS), "r1 and r2 held");
            assertTrue(atTen.await(LONG, TimeUnit.SECONDS), "r3 at step 10");
            List<robosim.hardware.HardwareSimulator> sims = List.of(
                    new robosim.hardware.HardwareSimulator("r1", robosim.devices.RobotTypes.byName("ArRobot")),
                    new robosim.hardware.HardwareSimulator("r2", robosim.devices.RobotTypes.byName("ArRobot")));
            CompletableFuture<Void> newProcess = CompletableFuture.runAsync(() -> {
                try {
                    robosim.hardware.ManyRobots.runOverOneConnection(sims, List.of(new robosim.examples.BackAndForth(),
                            new robosim.examples.BackAndForth()),
                            new java.net.Socket(InetAddress.getLoopbackAddress(), port), 64, null);
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            newProcess.get(LONG, TimeUnit.SECONDS);
            r3.get(LONG, TimeUnit.SECONDS);
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            RunSummary summary = env.summary();
            assertTrue(summary.completed(), summary.reason());
            assertEquals(List.of(), summary.departures());
            for (robosim.hardware.HardwareSimulator sim : sims) {
                assertEquals("completed " + STEPS + " steps", sim.endReason());
                assertEquals(STEPS - 10, sim.steps(), sim.name() + ": steps 10 to the end");
            }
        } finally {
            env.close();
        }
    }

    @Test
    void aSequentialEnvironmentRefusesASharedConnectionAsAWholeBeforeItsHellos() throws Exception {
        try (ClientWorkerCoordinator env = start(Settings.builder().design(
                robosim.environment.run.CoordinatorDesign.SEQUENTIAL))) {
            java.io.IOException e = org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class,
                    () -> new RawSharedRobots(env.ports()[0], List.of("r1", "r2"), robosim.devices.RobotTypes.properties("ArRobot")));
            assertEquals("refused before the hellos, 2 refusals: a shared connection needs the THREADS or TWO_THREADS "
                    + "coordinator (SEQUENTIAL reads a socket per robot; run the robots with --connection PER_ROBOT)",
                    e.getMessage());
        }
    }
}
