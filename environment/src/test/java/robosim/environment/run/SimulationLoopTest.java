package robosim.environment.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.environment.core.JoinRule;
import robosim.environment.core.WorldSpec;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.devices.DeviceSpec;
import robosim.environment.core.ThreadRecordingSensor;
import robosim.protocol.Arena;
import robosim.protocol.RobotHello;

/**
 * The {@link SimulationLoop} on its own thread, driving a {@link Run} with robots that post to it and in-process
 * geometry: no coordinator, no sockets, no worker threads. What it shows is the loop's: every step, and every
 * deadline, runs on its thread, and whoever waits on an event it will never take is answered. (What the run does
 * is {@link RunTest}'s, by hand.)
 */
class SimulationLoopTest {
    private static final long LONG_S = 60;
    private static final List<DeviceSpec> THREAD = List.of(new DeviceSpec("thread",
            ThreadRecordingSensor.class.getName(), Map.of()));
    private static final WorldSpec THREE = new WorldSpec("mem", "three", 500, 1, new Arena(0, 0, 20_000, 20_000),
            List.of(), List.of(new RobotSpec("a", "ArRobot", "", 2000, 2000, 0, THREAD, 0),
                    new RobotSpec("b", "ArRobot", "", 2000, 6000, 0, THREAD, 0),
                    new RobotSpec("c", "ArRobot", "", 2000, 10_000, 0, THREAD, 0)), 0, 8192, List.of());

    /** The names of the threads the listener was called on, and the departures it was told. */
    private final List<String> threads = new CopyOnWriteArrayList<>();
    private final List<Departure> left = new CopyOnWriteArrayList<>();
    private SimulationLoop loop;
    private Run run;

    /** A run on its loop thread, three robots that said hello. */
    private List<Bot> run(Settings settings, long cSilentFrom) throws Exception {
        CompletableFuture<Void> ended = new CompletableFuture<>();
        loop = new SimulationLoop(64, settings, () -> ended.complete(null));
        run = new Run(THREE, settings, new HelloCheck(THREE), System::nanoTime, new RunListener() {
            @Override
            public void robotLeft(Departure d) {
                threads.add(Thread.currentThread().getName());
                left.add(d);
            }

            @Override
            public void ended(RunSummary s) {
                threads.add(Thread.currentThread().getName());
            }
        }, List.of());
        loop.start(run, List.of());
        List<Bot> robots = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            Bot r = new Bot(loop::post, THREE.robots().get(i).name(), Bot.NEVER, i == 2 ? cSilentFrom : Bot.NEVER)
                    .reads("thread");
            assertNull(r.hello(i).get(LONG_S, TimeUnit.SECONDS), "accepted");
            robots.add(r);
        }
        return robots;
    }

    @Test
    void everyStepRunsOnTheLoopThread() throws Exception {
        ThreadRecordingSensor.THREADS.clear();
        List<Bot> robots = run(Settings.builder().inProcessGeometry(true).maxSteps(20).build(), Bot.NEVER);
        assertTrue(loop.awaitEnd(LONG_S, TimeUnit.SECONDS));
        for (Bot r : robots) {
            assertEquals(20, r.responses.size());
            for (int k = 0; k < 20; k++) {
                assertEquals(k, r.responses.get(k).step());
            }
            assertEquals("completed 20 steps", r.end.reason());
        }
        assertTrue(run.published().summary(3).completed());
        assertEquals(Set.of("simulation-loop"), ThreadRecordingSensor.THREADS);
        assertEquals(List.of("simulation-loop"), threads, "the end is told on the loop");
    }

    @Test
    void aSilentRobotIsDroppedByTheStepTimeoutOnTheLoopThread() throws Exception {
        ThreadRecordingSensor.THREADS.clear();
        List<Bot> robots = run(Settings.builder().inProcessGeometry(true).maxSteps(30).stepTimeoutMs(100).build(), 5);
        assertTrue(loop.awaitEnd(LONG_S, TimeUnit.SECONDS));
        RunSummary s = run.published().summary(3);
        assertTrue(s.completed(), s.reason());
        assertEquals(30, s.steps());
        assertEquals(1, left.size());
        assertEquals("c", left.get(0).robot());
        assertEquals(5, left.get(0).step());
        assertTrue(robots.get(2).dropped(), "its connection was closed");
        assertEquals(Set.of("simulation-loop"), Set.copyOf(threads), "the timeout acted on the loop");
        assertEquals(Set.of("simulation-loop"), ThreadRecordingSensor.THREADS, "every step ran on the loop");
    }

    @Test
    void everyoneWaitingOnAnEventStillQueuedWhenTheRunEndsIsAnsweredAtOnce() {
        SimulationLoop never = new SimulationLoop(64, Settings.builder().inProcessGeometry(true).build(), () -> { });
        CompletableFuture<Void> resumed = new CompletableFuture<>();
        CompletableFuture<Void> paused = new CompletableFuture<>();
        CompletableFuture<Long> stepped = new CompletableFuture<>();
        CompletableFuture<String> added = new CompletableFuture<>();
        CompletableFuture<String> removed = new CompletableFuture<>();
        CompletableFuture<String> hello = new CompletableFuture<>();
        never.post(new LoopEvent.Resume(resumed)); // (queued: no loop takes them)
        never.post(new LoopEvent.Pause(paused));
        never.post(new LoopEvent.StepN(3, stepped));
        never.post(new LoopEvent.AddRobot(new JoinRule("z", THREE.robots().get(0), null, 1), added));
        never.post(new LoopEvent.RemoveRobot("a", removed));
        never.post(new LoopEvent.HellosCome(Hellos.of(new Hellos.Hello(new Bot(never::post, "a", Bot.NEVER, 0),
                new RobotHello("a", robosim.devices.RobotTypes.properties("ArRobot")), 0, hello))));
        never.never(); // (the loop is done, as the run's end races these callers)
        assertTrue(resumed.isDone(), "resume() is answered, not left to its 5 s limit");
        assertTrue(paused.isDone());
        assertNull(stepped.getNow(-1L), "step N: refused, the caller reads the steps released");
        assertEquals(Progress.OVER, added.getNow(null));
        assertEquals(Progress.OVER, removed.getNow(null));
        assertEquals(Progress.OVER, hello.getNow(null));
        CompletableFuture<Void> late = new CompletableFuture<>();
        never.post(new LoopEvent.Resume(late));
        assertTrue(late.isDone(), "and one posted after the end");
    }
}
