package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.examples.BackAndForth;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * An Environment recording a run is killed (SIGKILL) in the middle of it: the file reads without error
 * up to the last step it holds whole, every step it holds is the one the viewers got, and it says that
 * the run's end is missing.
 */
class RecordingCrashTest {
    private static final long LONG_S = 60;

    @Test
    void aKilledEnvironmentLeavesARecordingReadableUpToItsLastWholeStep(@TempDir Path dir) throws Exception {
        Path envFile = InJvmSimulation.env("paper-benchmark.xml");
        Path file = dir.resolve("run.rec");
        ProcessLines env = new ProcessLines("environment", new ProcessBuilder(ProcessLines.java(List.of(),
                "robosim.environment.EnvironmentMain", envFile.toString(), "--steps", "1000000", "--no-geometry",
                "--robot-port", "0", "--viewer-port", "0", "--control-port", "-1", "--record", file.toString())));
        try (env) {
            Map<String, String> ports = HeadlessRunner.fields(env.await("listening robots=", LONG_S));
            int robotPort = Integer.parseInt(ports.get("robots"));
            Map<Long, PoseUpdate> seen = new ConcurrentHashMap<>();
            CountDownLatch far = new CountDownLatch(1);
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", Integer.parseInt(ports.get("viewers")),
                    new ViewerHello(true), LONG_S * 1000, null);
            viewer.start(new ViewerClient.Listener() {
                @Override
                public void snapshot(WorldSnapshot snapshot) {
                }

                @Override
                public void update(PoseUpdate u) {
                    seen.put(u.step(), u);
                    if (u.step() >= 1500) {
                        far.countDown();
                    }
                }
            });
            WorldSpec spec = new EnvironmentLoader().load(envFile);
            for (WorldSpec.RobotSpec r : spec.robots()) {
                HardwareSimulator sim = new HardwareSimulator(r.name(), robosim.devices.RobotTypes.byName(r.type()));
                sim.connect(new Socket(InetAddress.getLoopbackAddress(), robotPort), 64, null);
                Thread t = new Thread(() -> {
                    try {
                        sim.run(new BackAndForth());
                    } catch (Exception expected) {
                        // the Environment is killed under it
                    }
                }, "test-robot[" + r.name() + "]");
                t.setDaemon(true);
                t.start();
            }
            assertTrue(far.await(LONG_S, TimeUnit.SECONDS), "the run reached step 1500");

            env.process.destroyForcibly(); // SIGKILL, mid-run
            assertTrue(env.process.waitFor(LONG_S, TimeUnit.SECONDS));
            viewer.close();

            try (RecordingReader r = new RecordingReader(file)) {
                assertNull(r.end(), "the run never ended");
                assertEquals(spec.robots().size(), r.snapshot().robotNames().size());
                for (int k = 0; k < r.steps(); k++) {
                    assertEquals(k, r.stepNumber(k), "steps in order, none missing");
                    PoseUpdate got = seen.get((long) k);
                    if (got != null) { // (the viewer may have been killed off before taking the last ones)
                        assertArrayEquals(RecordingRunTest.bytes(got), RecordingRunTest.bytes(r.step(k).update()),
                                "step " + k);
                    }
                }
            }
        }
    }
}
