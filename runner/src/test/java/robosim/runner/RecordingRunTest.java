package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.RobotView;

/**
 * {@code --record}: a run's recording holds, step for step, exactly what a recording viewer got (byte for
 * byte), every message delivered, and the end.
 */
class RecordingRunTest {
    @Test
    void theRecordingHoldsWhatTheViewersGotAndEveryMessage(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("run.rec");
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .settings(s -> s.record(file).liveMetrics(true))
                .run(300, false, Chatter::new);
        assertTrue(sim.summary.completed(), sim.summary.reason());
        try (RecordingReader r = new RecordingReader(file)) {
            assertEquals(sim.updates.size(), r.steps());
            for (int k = 0; k < r.steps(); k++) {
                assertArrayEquals(bytes(sim.updates.get(k)), bytes(r.step(k).update()), "step " + k);
            }
            long messages = 0;
            long sent = 0;
            for (int k = 0; k < r.steps(); k++) {
                for (RobotView v : r.step(k).views()) {
                    messages += v.delivered().size();
                    sent += v.sent().size();
                }
            }
            assertTrue(messages > 0, "Chatter robots talk");
            assertTrue(sent > 0, "and what they sent is recorded too");
            assertEquals(sim.summary.messagesDelivered(), messages, "every message delivered is recorded");
            assertEquals("completed 300 steps", r.end().reason());
            assertNull(r.cutShort());
        }
        assertEquals(sim.metrics, robosim.sweep.RunMetrics.of(file, java.util.List.of(), 0.5).entrySet().stream()
                .filter(e -> sim.metrics.containsKey(e.getKey()))
                .collect(java.util.stream.Collectors.toMap(java.util.Map.Entry::getKey, java.util.Map.Entry::getValue)),
                "the built-in metrics counted live are the recording's, bit for bit (one implementation)");
        assertTrue(sim.metrics.get("messages_delivered") > 0 && sim.metrics.get("distance_m") > 0, sim.metrics.toString());
    }

    /** Broadcasts every step. */
    static final class Broadcaster implements robosim.api.RobotControl {
        @Override
        public void run(robosim.api.Robot robot) throws InterruptedException {
            for (int i = 0; true; i++) {
                robot.broadcast("step " + i);
                robot.move(100);
            }
        }
    }

    @Test
    void aRobotThatLeavesIsCountedLiveAsTheRecordingCountsIt(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("leaving.rec");
        java.util.concurrent.CompletableFuture<robosim.environment.net.ClientWorkerCoordinator> env =
                new java.util.concurrent.CompletableFuture<>();
        java.util.concurrent.atomic.AtomicBoolean removed = new java.util.concurrent.atomic.AtomicBoolean();
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("wander.xml"))
                .settings(s -> s.record(file).liveMetrics(true)).sideline((e, ports) -> env.complete(e))
                .onUpdate((u, port) -> { // (w1 removed mid-run, while the others broadcast to it; live and
                    // recorded agree at whatever moment of a step the loop takes the removal)
                    if (u.step() >= 30 && !removed.getAndSet(true)) {
                        try {
                            assertNull(env.get().roster().remove("w1"));
                        } catch (Exception ex) {
                            throw new AssertionError(ex);
                        }
                    }
                }).run(80, true, Broadcaster::new);
        assertEquals(5.0, sim.metrics.get("robots_left"), "w1 left");
        assertEquals(sim.metrics, robosim.sweep.RunMetrics.of(file, java.util.List.of(), 0.5).entrySet().stream()
                .filter(e -> sim.metrics.containsKey(e.getKey()))
                .collect(java.util.stream.Collectors.toMap(java.util.Map.Entry::getKey, java.util.Map.Entry::getValue)),
                "live and recorded, bit for bit, with a robot gone mid-run");
    }

    @Test
    void recordToolsReadingsAreEveryValueWithItsSensorsUnit(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("sensors.rec");
        new InJvmSimulation(InJvmSimulation.env("sensors.xml")).settings(s -> s.record(file)).run(5, false,
                Chatter::new);
        java.io.StringWriter text = new java.io.StringWriter();
        try (RecordingReader r = new RecordingReader(file); java.io.BufferedWriter out = new java.io.BufferedWriter(text)) {
            RecordToolMain.readings(r, out);
        }
        java.util.List<String> rows = text.toString().lines().toList();
        assertEquals("step,robot,sensor,unit,index,value", rows.get(0));
        assertTrue(rows.stream().anyMatch(l -> l.startsWith("1,f1,laser,mm,180,")), "a laser's last beam, in mm");
        assertTrue(rows.stream().anyMatch(l -> l.startsWith("1,f1,bump,,3,")), "a bump's right side, no unit");
        assertEquals(5 * 3 * (181 + 1 + 4), rows.size() - 1, "5 steps of 3 robots' laser, heat and bump");
    }

    static byte[] bytes(java.io.Externalizable u) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream o = new ObjectOutputStream(b)) {
            u.writeExternal(o);
        }
        return b.toByteArray();
    }
}
