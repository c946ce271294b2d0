package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.RobotLoss;
import robosim.environment.run.RunListener;
import robosim.environment.run.Settings;
import robosim.protocol.CommEvent;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Returns under {@code --on-robot-loss HOLD} at the edges: a new process that says hello while the run is
 * held, before the old one's loss has taken effect; every robot away at once (the world waits, and still
 * answers); a robot added from the control port that comes back. Robots by hand ({@link RawRobot}).
 */
class RobotReturnTest {
    private static final long LONG = 60;
    private static final int STEPS = 200;

    private static ClientWorkerCoordinator start(boolean paused) throws Exception {
        return start(paused, STEPS);
    }

    /** @param steps the run's steps (0: until stopped) */
    private static ClientWorkerCoordinator start(boolean paused, long steps) throws Exception {
        Settings s = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true)
                .maxSteps(steps).resetEvery(64).onRobotLoss(RobotLoss.HOLD).build();
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(
                new EnvironmentLoader().load(Path.of("src/test/resources/three-robots.xml")), s);
        if (paused) {
            env.startPaused();
        }
        env.start();
        return env;
    }

    /** {@code name} by hand to the end; r2 sends r1 its step number every step. */
    private static CompletableFuture<Void> steps(String name, int port) {
        return CompletableFuture.runAsync(() -> {
            try (RawRobot r = new RawRobot(name, name.equals("r3") ? robosim.devices.RobotTypes.properties("Scout") : robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                while (r.next() && r.step(0, 0, false, name.equals("r2")
                        ? List.of(new CommEvent("r2", "r1", Long.toString(r.step))) : List.of()) != null) {
                    // (to the end)
                }
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
    }

    /** Waits (60 s at most) until the Environment has seen robot {@code name}'s connection close. */
    private static void awaitClosed(ClientWorkerCoordinator env, String name) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(LONG);
        while (env.status().connected().contains(name)) {
            assertTrue(System.nanoTime() - deadline < 0, name + "'s connection is still open at the Environment");
            Thread.sleep(5); // (its worker thread notices the close on its own; nothing to wait on but that)
        }
    }

    private static CountDownLatch held(ClientWorkerCoordinator env, int robots) {
        CountDownLatch held = new CountDownLatch(robots);
        env.listen(new RunListener() {
            @Override
            public void robotHeld(String robot, long step, String why) {
                held.countDown();
            }
        });
        return held;
    }

    @Test
    void aProcessThatSaysHelloWhileTheRunIsHeldBeforeTheOldOneIsGoneTakesOverAtTheNextStep() throws Exception {
        try (ClientWorkerCoordinator env = start(true)) {
            int port = env.ports()[0];
            CountDownLatch sentTen = new CountDownLatch(1);
            CountDownLatch close = new CountDownLatch(1);
            List<String> inbox = new ArrayList<>();
            CompletableFuture<Void> first = CompletableFuture.runAsync(() -> {
                try (RawRobot r1 = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                    while (r1.next() && r1.step < 10) {
                        r1.step(0, 0, false, List.of()).inbox().forEach(m -> inbox.add(m.payload()));
                    }
                    r1.connection.write(new StepRequest(10, 0, 0, false, List.of())); // (its response never read)
                    r1.connection.flush();
                    sentTen.countDown();
                    close.await(LONG, TimeUnit.SECONDS);
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            CompletableFuture<Void> r2 = steps("r2", port);
            CompletableFuture<Void> r3 = steps("r3", port);
            assertTrue(env.awaitStart(LONG, TimeUnit.SECONDS));
            env.step(10, LONG, TimeUnit.SECONDS);
            assertTrue(sentTen.await(LONG, TimeUnit.SECONDS));
            env.pause(LONG, TimeUnit.SECONDS); // step 10 is computed and held, r1's request in it
            close.countDown();
            first.get(LONG, TimeUnit.SECONDS); // its connection closed, whether or not the loop has heard yet
            awaitClosed(env, "r1"); // (the Environment's end of it too: a hello before that is "already connected")
            try (RawRobot again = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertTrue(again.welcome.isAccepted(), again.welcome.reason());
                env.resume();
                assertTrue(again.next());
                assertEquals(11, again.step, "it takes over at the step after the one held");
                StepResponse back = again.step(0, 0, false, List.of());
                assertEquals(List.of("10", "11"), back.inbox().stream().map(CommEvent::payload).toList(),
                        "step 10's messages, which the old connection never got, come first");
                back.inbox().forEach(m -> inbox.add(m.payload()));
                while (again.next()) {
                    again.step(0, 0, false, List.of()).inbox().forEach(m -> inbox.add(m.payload()));
                }
            }
            r2.get(LONG, TimeUnit.SECONDS);
            r3.get(LONG, TimeUnit.SECONDS);
            assertEquals(STEPS, inbox.size());
            for (int k = 0; k < STEPS; k++) {
                assertEquals(Integer.toString(k), inbox.get(k), "every message once, in order");
            }
        }
    }

    @Test
    void whenEveryRobotIsAwayTheWorldWaitsAndStillAnswers() throws Exception {
        try (ClientWorkerCoordinator env = start(false)) {
            int port = env.ports()[0];
            CountDownLatch allHeld = held(env, 3);
            List<CompletableFuture<Void>> fiveSteps = new ArrayList<>();
            for (String name : List.of("r1", "r2", "r3")) {
                fiveSteps.add(CompletableFuture.runAsync(() -> {
                    try (RawRobot r = new RawRobot(name, name.equals("r3") ? robosim.devices.RobotTypes.properties("Scout") : robosim.devices.RobotTypes.properties("ArRobot"),
                            port)) {
                        for (int k = 0; k < 5 && r.next(); k++) {
                            r.step(0, 0, false, List.of());
                        }
                    } catch (Exception e) {
                        throw new IllegalStateException(e);
                    }
                }, TestThreads.ROBOTS));
            }
            for (CompletableFuture<Void> f : fiveSteps) {
                f.get(LONG, TimeUnit.SECONDS); // (five steps each, then its connection closes)
            }
            assertTrue(allHeld.await(LONG, TimeUnit.SECONDS), "all three held");
            assertEquals("no robot named \"nobody\" in this simulation", env.roster().remove("nobody"),
                    "the loop answers (it is not spinning through the steps)");
            long at = env.status().step();
            assertTrue(at < STEPS, "the world waited at step " + at);
            try (RawRobot r1 = new RawRobot("r1", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertTrue(r1.welcome.isAccepted(), r1.welcome.reason());
                int steps = 0;
                while (r1.next()) {
                    assertEquals(at + steps, r1.step);
                    r1.step(0, 0, false, List.of());
                    steps++;
                }
                assertEquals("completed " + STEPS + " steps", r1.endReason, "it runs on alone to the end");
            }
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
        }
    }

    @Test
    void aRobotAddedFromTheControlPortComesBackUnderHold() throws Exception {
        try (ClientWorkerCoordinator env = start(false, 0)) { // (until stopped: the others wait for nothing here)
            int port = env.ports()[0];
            CountDownLatch held = held(env, 1);
            CompletableFuture<Void> r1 = steps("r1", port);
            CompletableFuture<Void> r2 = steps("r2", port);
            CompletableFuture<Void> r3 = steps("r3", port);
            assertTrue(env.awaitStart(LONG, TimeUnit.SECONDS));
            assertNull(env.roster().add("r9", "Scout", 11, 2, 180, ""));
            try (RawRobot r9 = new RawRobot("r9", robosim.devices.RobotTypes.properties("Scout"), port)) {
                assertTrue(r9.welcome.isAccepted(), r9.welcome.reason());
                assertTrue(r9.next());
                r9.step(50, 0, false, List.of());
            }
            assertTrue(held.await(LONG, TimeUnit.SECONDS), "r9 is held");
            try (RawRobot again = new RawRobot("r9", robosim.devices.RobotTypes.properties("Scout"), port)) {
                assertTrue(again.welcome.isAccepted(), again.welcome.reason());
                assertEquals(11_000 - 50, again.welcome.xMm(), 1e-6, "where it stood");
                for (int k = 0; k < 3; k++) {
                    assertTrue(again.next());
                    again.step(0, 0, false, List.of());
                }
                env.stop("done");
                while (again.next() && again.step(0, 0, false, List.of()) != null) {
                    // (to the end)
                }
                assertEquals("done", again.endReason);
            }
            r1.get(LONG, TimeUnit.SECONDS);
            r2.get(LONG, TimeUnit.SECONDS);
            r3.get(LONG, TimeUnit.SECONDS);
        }
    }
}
