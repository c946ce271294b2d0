package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.CoordinatorDesign;
import robosim.environment.run.Departure;
import robosim.environment.run.RobotLoss;
import robosim.environment.run.RunListener;
import robosim.environment.run.RunSummary;
import robosim.environment.run.Settings;
import robosim.protocol.CommEvent;
import robosim.protocol.RobotProperties;
import robosim.protocol.StepResponse;

/**
 * {@code --on-robot-loss}: a robot whose connection closes mid-run is held in the world (HOLD), or the world
 * waits for it (WAIT), and a new connection with its name takes it over where it stood, with every message
 * sent to it meanwhile, once and in order. Robots by hand ({@link RawRobot}), so each step is known.
 */
class RobotLossTest {
    private static final long LONG = 60;
    private static final int STEPS = 200;
    /** r1 moves this far a step (ArRobot's limit at the file's 500 ms step is far more). */
    private static final double MOVE_MM = 40;
    /**
     * The step timeout where a test needs one (as FaultsTest's): long enough that a robot which answers is never
     * late on a loaded machine, short enough for the suite.
     */
    private static final long STEP_TIMEOUT_MS = 2000;

    private static ClientWorkerCoordinator start(RobotLoss loss, CoordinatorDesign design, long stepTimeoutMs)
            throws Exception {
        Settings s = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true)
                .maxSteps(STEPS).resetEvery(64).design(design).onRobotLoss(loss).stepTimeoutMs(stepTimeoutMs).build();
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(
                new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml")), s);
        env.start();
        return env;
    }

    /**
     * r2: sends r1 its step number every step; before the request for step {@code waitAt} it waits for
     * {@code go} (the world waits with it). r3 stands still. Both to the end; r2 returns its last step.
     */
    private static CompletableFuture<Long> others(int port, long waitAt, CountDownLatch reached, CountDownLatch go) {
        CompletableFuture<Void> r3 = CompletableFuture.runAsync(() -> standStill("r3", port), TestThreads.ROBOTS);
        return CompletableFuture.supplyAsync(() -> {
            try (RawRobot r2 = new RawRobot("r2", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertTrue(r2.welcome.isAccepted(), r2.welcome.reason());
                long last = -1;
                while (r2.next()) {
                    if (r2.step == waitAt) {
                        reached.countDown();
                        if (!go.await(LONG, TimeUnit.SECONDS)) {
                            throw new AssertionError("r1 did not come back");
                        }
                    }
                    last = r2.step(0, 0, false, List.of(new CommEvent("r2", "r1", Long.toString(r2.step)))).step();
                }
                r3.get(LONG, TimeUnit.SECONDS);
                return last;
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
    }

    private static void standStill(String name, int port) {
        try (RawRobot r = new RawRobot(name, robosim.devices.RobotTypes.properties("Scout"), port)) {
            while (r.next()) {
                r.step(0, 0, false, List.of());
            }
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    /** Counted down when a robot is held (the loop has heard that its connection closed). */
    private static CountDownLatch held(ClientWorkerCoordinator env) {
        CountDownLatch held = new CountDownLatch(1);
        env.listen(new RunListener() {
            @Override
            public void robotHeld(String robot, long step, String why) {
                held.countDown();
            }
        });
        return held;
    }

    /** r1 for {@code steps} steps, moving, its messages' texts added to {@code inbox}; returns its last response. */
    private static StepResponse r1Steps(RawRobot r1, int steps, List<String> inbox) throws Exception {
        StepResponse last = null;
        for (int i = 0; i < steps && r1.next(); i++) {
            last = r1.step(MOVE_MM, 0, false, List.of());
            assertEquals(r1.step, last.step());
            last.inbox().forEach(m -> inbox.add(m.payload()));
        }
        return last;
    }

    private static List<String> numbers(int from, int to) {
        List<String> l = new ArrayList<>();
        for (int i = from; i < to; i++) {
            l.add(Integer.toString(i));
        }
        return l;
    }

    @ParameterizedTest
    @EnumSource(value = CoordinatorDesign.class, names = {"THREADS", "TWO_THREADS"})
    void underHoldALostRobotStandsAndANewConnectionTakesItOverWithEveryMessage(CoordinatorDesign design)
            throws Exception {
        try (ClientWorkerCoordinator env = start(RobotLoss.HOLD, design, 0)) {
            int port = env.ports()[0];
            CountDownLatch at41 = new CountDownLatch(1);
            CountDownLatch back = new CountDownLatch(1);
            CompletableFuture<Long> others = others(port, 41, at41, back);
            List<String> inbox = new ArrayList<>();
            StepResponse before;
            try (RawRobot r1 = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                before = r1Steps(r1, 20, inbox); // steps 0..19, then its connection closes
            }
            assertTrue(at41.await(LONG, TimeUnit.SECONDS), "the others went on without it");
            try (RawRobot again = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertTrue(again.welcome.isAccepted(), again.welcome.reason());
                assertEquals(before.xMm(), again.welcome.xMm(), "it comes back where it stood");
                assertEquals(before.yMm(), again.welcome.yMm());
                assertEquals(before.headingDeg(), again.welcome.headingDeg());
                back.countDown();
                StepResponse first = r1Steps(again, 1, inbox);
                assertEquals(41, again.firstStep, "held for steps 20 to 40 (r2 held step 41 until it was back)");
                assertEquals(before.xMm() + MOVE_MM, first.xMm(), 1e-9, "it moves on from there");
                assertEquals(numbers(20, 42), first.inbox().stream().map(CommEvent::payload).toList(),
                        "what was sent to it while away comes in its first response, in order");
                r1Steps(again, STEPS, inbox);
                assertEquals("completed " + STEPS + " steps", again.endReason);
            }
            assertEquals(STEPS - 1, others.get(LONG, TimeUnit.SECONDS));
            assertEquals(numbers(0, STEPS), inbox, "every message once, in order");
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            RunSummary s = env.summary();
            assertTrue(s.completed(), s.reason());
            assertEquals(0, s.robotsRemoved(), "a robot that came back has not left");
        }
    }

    @Test
    void underWaitTheWorldStopsUntilTheRobotIsBack() throws Exception {
        try (ClientWorkerCoordinator env = start(RobotLoss.WAIT, CoordinatorDesign.THREADS, 0)) {
            CountDownLatch held = held(env);
            int port = env.ports()[0];
            CompletableFuture<Long> others = others(port, -1, new CountDownLatch(1), new CountDownLatch(0));
            List<String> inbox = new ArrayList<>();
            try (RawRobot r1 = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                r1Steps(r1, 20, inbox);
            }
            assertTrue(held.await(LONG, TimeUnit.SECONDS), "r1 is held");
            try (RawRobot again = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertTrue(again.welcome.isAccepted(), again.welcome.reason());
                assertTrue(again.next());
                assertEquals(20, again.step, "the world waited at the step it was lost in");
                assertFalse(others.isDone());
                again.step(MOVE_MM, 0, false, List.of()).inbox().forEach(m -> inbox.add(m.payload()));
                r1Steps(again, STEPS, inbox);
            }
            assertEquals(STEPS - 1, others.get(LONG, TimeUnit.SECONDS));
            assertEquals(numbers(0, STEPS), inbox);
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            assertTrue(env.summary().completed(), env.summary().reason());
        }
    }

    @Test
    void underWaitARobotThatDoesNotComeBackWithinTheStepTimeoutIsRemoved() throws Exception {
        try (ClientWorkerCoordinator env = start(RobotLoss.WAIT, CoordinatorDesign.THREADS, STEP_TIMEOUT_MS)) {
            int port = env.ports()[0];
            CompletableFuture<Long> others = others(port, -1, new CountDownLatch(1), new CountDownLatch(0));
            try (RawRobot r1 = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                r1Steps(r1, 20, new ArrayList<>());
            }
            assertEquals(STEPS - 1, others.get(LONG, TimeUnit.SECONDS));
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            RunSummary s = env.summary();
            assertTrue(s.completed(), s.reason());
            assertEquals(1, s.robotsRemoved());
            assertEquals("r1", s.departures().get(0).robot());
            assertEquals(20, s.departures().get(0).step());
            assertTrue(s.departures().get(0).why().contains("did not come back within " + STEP_TIMEOUT_MS + " ms"),
                    s.departures().get(0).why());
        }
    }

    @Test
    void aNameThatIsStillConnectedRemovedOrComesBackAsAnotherRobotIsRefused() throws Exception {
        try (ClientWorkerCoordinator env = start(RobotLoss.HOLD, CoordinatorDesign.THREADS, 0)) {
            CountDownLatch held = held(env);
            int port = env.ports()[0];
            CountDownLatch done = new CountDownLatch(1);
            CompletableFuture<Long> others = others(port, 30, new CountDownLatch(1), done);
            try (RawRobot r1 = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                r1Steps(r1, 20, new ArrayList<>());
                try (RawRobot twin = new RawRobot("r2", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                    assertFalse(twin.welcome.isAccepted());
                    assertTrue(twin.welcome.reason().startsWith("robot r2 is already connected"), twin.welcome.reason());
                }
            }
            RobotProperties faster = new RobotProperties("ArRobot", robosim.devices.RobotTypes.properties("ArRobot").radiusMm(),
                    2 * robosim.devices.RobotTypes.properties("ArRobot").maxSpeedMmPerS(), robosim.devices.RobotTypes.properties("ArRobot").maxTurnDegPerS(),
                    robosim.devices.RobotTypes.properties("ArRobot").sonars());
            assertTrue(held.await(LONG, TimeUnit.SECONDS), "r1 is held");
            try (RawRobot other = new RawRobot("r1", faster, port)) {
                assertFalse(other.welcome.isAccepted());
                assertTrue(other.welcome.reason().startsWith("robot r1 comes back with a top speed of"),
                        other.welcome.reason());
            }
            done.countDown();
            assertEquals(STEPS - 1, others.get(LONG, TimeUnit.SECONDS));
        }
        try (ClientWorkerCoordinator env = start(RobotLoss.REMOVE, CoordinatorDesign.THREADS, 0)) {
            CountDownLatch left = new CountDownLatch(1);
            env.listen(new RunListener() {
                @Override
                public void robotLeft(Departure departure) {
                    left.countDown();
                }
            });
            int port = env.ports()[0];
            CountDownLatch done = new CountDownLatch(1);
            CompletableFuture<Long> others = others(port, 30, new CountDownLatch(1), done);
            try (RawRobot r1 = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                r1Steps(r1, 20, new ArrayList<>());
            }
            assertTrue(left.await(LONG, TimeUnit.SECONDS), "r1 is removed");
            try (RawRobot again = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertFalse(again.welcome.isAccepted());
                assertTrue(again.welcome.reason().contains("--on-robot-loss HOLD or WAIT"), again.welcome.reason());
            }
            done.countDown();
            assertEquals(STEPS - 1, others.get(LONG, TimeUnit.SECONDS));
        }
    }
}
