package robosim.environment.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import robosim.environment.core.WorldSpec;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.environment.core.WorldSpec.SensorSpec;
import robosim.environment.sensors.ThreadRecordingSensor;
import robosim.protocol.Arena;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotModels;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepResponse;

/**
 * The simulation loop with fake robots and in-process geometry: no sockets, no worker threads. Every
 * robot's request is posted before the loop could time it, so nothing here depends on timing.
 */
class SimulationLoopTest {
    private static final long LONG_S = 60;
    private static final List<SensorSpec> THREAD = List.of(new SensorSpec("thread",
            ThreadRecordingSensor.class.getName(), 0, Map.of()));
    private static final WorldSpec THREE = new WorldSpec("mem", "three", 500, 1, new Arena(0, 0, 20_000, 20_000),
            List.of(), List.of(new RobotSpec("a", "ArRobot", "", 2000, 2000, 0, THREAD, 0),
                    new RobotSpec("b", "ArRobot", "", 2000, 6000, 0, THREAD, 0),
                    new RobotSpec("c", "ArRobot", "", 2000, 10_000, 0, THREAD, 0)), 0, 8192, List.of());

    /** The names of the threads the listener was called on, and the departures it was told. */
    private static final class Heard implements RunListener {
        final List<String> threads = new CopyOnWriteArrayList<>();
        final List<Departure> left = new CopyOnWriteArrayList<>();

        @Override
        public void robotLeft(Departure d) {
            threads.add(Thread.currentThread().getName());
            left.add(d);
        }

        @Override
        public void ended(RunSummary s) {
            threads.add(Thread.currentThread().getName());
        }
    }

    private final Heard heard = new Heard();

    /** A coordinator whose loop runs (no ports bound) and three fake robots that have said hello. */
    private List<FakeRobot> run(UnaryOperator<Settings.Builder> settings, long silentFrom, boolean paused)
            throws Exception {
        ClientWorkerCoordinator c = new ClientWorkerCoordinator(THREE,
                settings.apply(Settings.builder().inProcessGeometry(true)).build());
        c.listen(heard);
        if (paused) {
            c.startPaused();
        }
        c.startLoop();
        coordinator = c;
        List<FakeRobot> robots = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            FakeRobot r = new FakeRobot(c, i, i == 2 ? silentFrom : Long.MAX_VALUE);
            CompletableFuture<String> verdict = new CompletableFuture<>();
            c.post(new LoopEvent.RobotJoins(r, new RobotHello(THREE.robots().get(i).name(), RobotModels.AR_ROBOT), i,
                    verdict));
            assertNull(verdict.get(LONG_S, TimeUnit.SECONDS), "accepted");
            robots.add(r);
        }
        return robots;
    }

    private ClientWorkerCoordinator coordinator;

    @Test
    void everyRobotGetsEveryResponseInOrderAndTheCoreRunsOnlyOnTheLoopThread() throws Exception {
        ThreadRecordingSensor.THREADS.clear();
        List<FakeRobot> robots = run(s -> s.maxSteps(20), Long.MAX_VALUE, false);
        assertTrue(coordinator.awaitEnd(LONG_S, TimeUnit.SECONDS));
        for (FakeRobot r : robots) {
            for (long k = 0; k < 20; k++) {
                StepResponse response = r.responses.poll(LONG_S, TimeUnit.SECONDS);
                assertNotNull(response);
                assertEquals(k, response.step());
                assertEquals(100, response.movedMm(), 1e-9, "nothing in the way");
            }
            assertEquals("completed 20 steps", r.ends.poll(LONG_S, TimeUnit.SECONDS).reason());
        }
        RunSummary s = coordinator.summary();
        assertTrue(s.completed(), s.reason());
        assertEquals(20, s.steps());
        assertEquals(Set.of("simulation-loop"), ThreadRecordingSensor.THREADS);
    }

    @Test
    void aSilentRobotIsDroppedByTheStepTimeoutOnTheLoopThreadAndTheOthersGoOn() throws Exception {
        ThreadRecordingSensor.THREADS.clear();
        List<FakeRobot> robots = run(s -> s.maxSteps(30).stepTimeoutMs(100), 5, false);
        assertTrue(coordinator.awaitEnd(LONG_S, TimeUnit.SECONDS));
        RunSummary s = coordinator.summary();
        assertTrue(s.completed(), s.reason());
        assertEquals(30, s.steps());
        assertEquals(1, heard.left.size());
        Departure d = heard.left.get(0);
        assertEquals("c", d.robot());
        assertEquals(5, d.step());
        assertTrue(d.why().contains("step timeout"), d.why());
        assertTrue(robots.get(2).dropped(), "its connection was closed");
        assertFalse(robots.get(0).dropped());
        assertEquals(Set.of("simulation-loop"), Set.copyOf(heard.threads), "the timeout acted on the loop");
        assertEquals(Set.of("simulation-loop"), ThreadRecordingSensor.THREADS, "every step ran on the loop");
    }

    @Test
    void stepNRunsExactlyNStepsPauseHoldsAndStopEndsAtOnce() throws Exception {
        List<FakeRobot> robots = run(s -> s, Long.MAX_VALUE, true);
        assertEquals(3, coordinator.step(3, LONG_S, TimeUnit.SECONDS));
        assertEquals(RunStatus.State.PAUSED, coordinator.status().state());
        assertEquals(3, coordinator.status().step());
        assertEquals(3, robots.get(0).responses.size(), "three responses out, the fourth step held");
        assertEquals(7, coordinator.step(4, LONG_S, TimeUnit.SECONDS));
        coordinator.resume();
        coordinator.pause(LONG_S, TimeUnit.SECONDS);
        assertEquals(RunStatus.State.PAUSED, coordinator.status().state());
        long held = coordinator.status().step();
        assertTrue(held >= 7, "ran on after the resume: " + held);
        coordinator.stop("stopped by the test");
        assertTrue(coordinator.awaitEnd(LONG_S, TimeUnit.SECONDS), "stop returns once the run has ended");
        assertEquals(RunStatus.State.ENDED, coordinator.status().state());
        SimulationEnd end = robots.get(1).ends.poll(LONG_S, TimeUnit.SECONDS);
        assertEquals("stopped by the test", end.reason());
        assertEquals(held, robots.get(1).responses.size(), "nothing went out after the pause held");
    }

    @Test
    void everyoneWaitingOnAnEventStillQueuedWhenTheRunEndsIsAnsweredAtOnce() throws Exception {
        ClientWorkerCoordinator c = new ClientWorkerCoordinator(THREE, Settings.builder().inProcessGeometry(true).build());
        CompletableFuture<Void> resumed = new CompletableFuture<>();
        CompletableFuture<Void> paused = new CompletableFuture<>();
        CompletableFuture<Long> stepped = new CompletableFuture<>();
        CompletableFuture<String> added = new CompletableFuture<>();
        CompletableFuture<String> removed = new CompletableFuture<>();
        CompletableFuture<String> hello = new CompletableFuture<>();
        c.post(new LoopEvent.Resume(resumed)); // (queued: no loop takes them)
        c.post(new LoopEvent.Pause(paused));
        c.post(new LoopEvent.StepN(3, stepped));
        c.post(new LoopEvent.AddRobot(new robosim.environment.core.JoinRule("z", THREE.robots().get(0), null, 1),
                added));
        c.post(new LoopEvent.RemoveRobot("a", removed));
        c.post(new LoopEvent.RobotJoins(new FakeRobot(c, 0, 0), new RobotHello("a", RobotModels.AR_ROBOT), 0, hello));
        c.loopEnded(); // (what the loop does last, as the run's end races these callers)
        assertTrue(resumed.isDone(), "resume() is answered, not left to its 5 s limit");
        assertTrue(paused.isDone());
        assertNull(stepped.getNow(-1L), "step N: refused, the caller reads the steps released");
        assertEquals(LoopEvent.OVER, added.getNow(null));
        assertEquals(LoopEvent.OVER, removed.getNow(null));
        assertEquals(LoopEvent.OVER, hello.getNow(null));
        CompletableFuture<Void> late = new CompletableFuture<>();
        c.post(new LoopEvent.Resume(late));
        assertTrue(late.isDone(), "and one posted after the end");
    }
}
