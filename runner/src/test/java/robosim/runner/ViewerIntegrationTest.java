package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.environment.core.WorldSpec;
import robosim.examples.BackAndForth;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;

/**
 * Three viewers on a 10-robot run of 952 steps, one of them never reading from its socket and no
 * viewer write deadline (so only the coalescing queue protects the robots): the run completes and the
 * live viewers see the final poses. That the frozen viewer's queue never holds more than one update
 * is {@code ViewerQueueTest}'s (environment module).
 */
class ViewerIntegrationTest {
    /**
     * 10 cycles of 88 and 72 more (the same end pose as 5000 steps): about 900 bytes an update, some 880 KB in
     * all, while the frozen viewer's 4 KB receive buffer, its stream's 64 KB buffer and the kernel's send buffer
     * (128 KB here, found full at the last step) hold some 200 KB, so its worker is stuck writing from about
     * step 220 on.
     */
    private static final int STEPS = 952;

    @Test
    void aFrozenViewerNeitherStopsTheRobotsNorGrowsTheEnvironment() throws Exception {
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .withViewers(2, 1)
                .settings(s -> s.writeTimeoutMs(0))
                .run(STEPS, false, BackAndForth::new);
        assertTrue(sim.summary.completed(), sim.summary.reason());
        assertEquals(STEPS, sim.summary.steps());
        // the recording and live viewers got the end and left; the frozen one is still there, its worker
        // stuck writing to a socket nobody reads
        assertEquals(1, sim.viewersAtEnd, "only the frozen viewer is still connected");
        List<WorldSpec.RobotSpec> robots = sim.spec.robots();
        for (PoseUpdate last : sim.liveLast) {
            assertEquals(STEPS - 1, last.step(), "a live viewer saw the last step");
            for (int i = 0; i < robots.size(); i++) {
                // 952 steps of BackAndForth: 3 m out on the way back, heading 180
                assertEquals(robots.get(i).xMm() + 3000, last.xMm(i), 1e-6);
                assertEquals(180, last.headingDeg(i));
            }
        }
    }

    @Test
    void aViewerJoiningMidRunGetsTheSnapshotThenEveryUpdateWithoutAGap() throws Exception {
        java.util.concurrent.CompletableFuture<ViewerClient> late = new java.util.concurrent.CompletableFuture<>();
        List<Long> lateSteps = java.util.Collections.synchronizedList(new java.util.ArrayList<>());
        long[] snapshotStep = {Long.MIN_VALUE};
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .onUpdate((u, port) -> {
                    if (u.step() == 500) {
                        // join from another thread while the run goes on
                        new Thread(() -> {
                            try {
                                ViewerClient v = ViewerClient.connect("127.0.0.1", port, true, 10_000);
                                v.start(new ViewerClient.Listener() {
                                    @Override
                                    public void snapshot(WorldSnapshot s) {
                                        snapshotStep[0] = s.step();
                                    }

                                    @Override
                                    public void update(PoseUpdate update) {
                                        lateSteps.add(update.step());
                                    }
                                });
                                late.complete(v);
                            } catch (Exception e) {
                                late.completeExceptionally(e);
                            }
                        }).start();
                    }
                })
                .run(2000, true, BackAndForth::new);
        ViewerClient v = late.get(30, java.util.concurrent.TimeUnit.SECONDS);
        assertEquals("completed 2000 steps", v.awaitEnd(30, java.util.concurrent.TimeUnit.SECONDS).reason());
        assertTrue(snapshotStep[0] >= 500 && snapshotStep[0] < 1999, "joined mid-run at " + snapshotStep[0]);
        assertEquals(1999 - snapshotStep[0], lateSteps.size(), "every step after the snapshot");
        for (int i = 0; i < lateSteps.size(); i++) {
            assertEquals(snapshotStep[0] + 1 + i, lateSteps.get(i), "no gap, no repeat");
        }
        assertTrue(sim.summary.completed());
    }
}
