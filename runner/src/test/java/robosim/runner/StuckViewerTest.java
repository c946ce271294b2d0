package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ObjectOutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.RunStatus;
import robosim.environment.run.Settings;
import robosim.examples.BackAndForth;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * A recording viewer that stops reading (a pose log on a full disk, a hung process) over real sockets:
 * the loop never waits on it. It holds a step back only while the viewer is a whole backlog behind, the
 * status and stop answer meanwhile, and past the viewer write timeout the viewer is dropped with its
 * reason and the run goes on.
 */
class StuckViewerTest {
    private static final long LONG_S = 60;
    private static final Path THREE = Path.of("src/test/resources/three-robots.xml");

    /** A recording viewer that says hello and never reads (a tiny receive buffer, so it fills at once). */
    private static Socket frozenRecorder(int port) throws Exception {
        Socket s = new Socket();
        s.setReceiveBufferSize(4096);
        s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
        ObjectOutputStream out = new ObjectOutputStream(s.getOutputStream());
        out.writeObject(new ViewerHello(true));
        out.flush();
        return s;
    }

    private static ClientWorkerCoordinator environment(long writeTimeoutMs, RunEvents events) throws Exception {
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(new EnvironmentLoader().load(THREE),
                Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true)
                        .writeTimeoutMs(writeTimeoutMs).build());
        env.listen(events);
        env.start();
        return env;
    }

    private static List<CompletableFuture<String>> robots(ClientWorkerCoordinator env) throws Exception {
        List<CompletableFuture<String>> out = new ArrayList<>();
        for (String name : List.of("r1", "r2", "r3")) {
            HardwareSimulator sim = new HardwareSimulator(name, robosim.devices.RobotTypes.byName(name.equals("r3") ? "Scout" : "ArRobot"));
            sim.connect(new Socket(InetAddress.getLoopbackAddress(), env.ports()[0]), 64);
            out.add(CompletableFuture.supplyAsync(() -> {
                try {
                    return sim.run(new BackAndForth());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS));
        }
        return out;
    }

    @Test
    void whileARecordingViewerIsStuckStatusAndStopAnswerWithinOneSecond() throws Exception {
        RunEvents events = new RunEvents();
        try (ClientWorkerCoordinator env = environment(0, events); Socket frozen = frozenRecorder(env.ports()[1])) {
            List<CompletableFuture<String>> robots = robots(env);
            assertTrue(events.heldForViewer.await(LONG_S, TimeUnit.SECONDS), "the viewer fell a whole backlog behind");
            long t0 = System.nanoTime();
            RunStatus status = env.status();
            long statusMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t0);
            assertEquals(RunStatus.State.RUNNING, status.state(), "held for a viewer is not a pause");
            assertTrue(statusMs < 1000, "status took " + statusMs + " ms");
            long t1 = System.nanoTime();
            env.stop("stopped while a viewer was stuck");
            long stopMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t1);
            assertEquals(RunStatus.State.ENDED, env.status().state());
            assertTrue(stopMs < 1000, "stop took " + stopMs + " ms");
            for (CompletableFuture<String> r : robots) {
                assertEquals("stopped while a viewer was stuck", r.get(LONG_S, TimeUnit.SECONDS));
            }
        }
    }

    @Test
    void aRecordingViewerThatTakesNoWriteWithinTheTimeoutIsDroppedAndTheRunGoesOn() throws Exception {
        RunEvents events = new RunEvents();
        try (ClientWorkerCoordinator env = environment(500, events); Socket frozen = frozenRecorder(env.ports()[1])) {
            BlockingQueue<PoseUpdate> seen = new LinkedBlockingQueue<>();
            ViewerClient live = ViewerClient.connect("127.0.0.1", env.ports()[1], false, 10_000);
            live.start(new ViewerClient.Listener() {
                @Override
                public void snapshot(WorldSnapshot snapshot) {
                }

                @Override
                public void update(PoseUpdate update) {
                    seen.add(update);
                }
            });
            List<CompletableFuture<String>> robots = robots(env);
            assertTrue(events.viewerDropped.await(LONG_S, TimeUnit.SECONDS), "the stuck viewer was dropped");
            assertEquals(1, events.droppedViewers.size());
            assertTrue(events.droppedViewers.get(0).endsWith("did not take a write within 500 ms"),
                    events.droppedViewers.get(0));
            long dropped = env.status().step();
            PoseUpdate later;
            do {
                later = seen.poll(LONG_S, TimeUnit.SECONDS);
                assertNotNull(later, "the run went on after the drop");
            } while (later.step() < dropped + 100);
            env.stop("enough");
            for (CompletableFuture<String> r : robots) {
                assertEquals("enough", r.get(LONG_S, TimeUnit.SECONDS));
            }
            live.close();
        }
    }
}
