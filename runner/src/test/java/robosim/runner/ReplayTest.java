package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.control.ControlClient;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;
import robosim.viewer.SceneFeed;
import robosim.viewer.StatusLine;

/**
 * {@code scripts/replay.sh}: a recording replayed in its own process gives a viewer what the live run gave
 * it, message for message and byte for byte, and the control port seeks, steps and stops it.
 */
class ReplayTest {
    private static final long LONG_S = 120;
    /**
     * The seek test's recording: long enough that a replay resumed at step 10 at its top speed (100 times real
     * time, 200 steps a second) runs for some 10 s before its end, so the viewer sees it go on from where it was
     * sought well before the end even on a loaded machine.
     */
    private static final int SEEK_STEPS = 2000;
    private static final int MIDDLE = SEEK_STEPS / 2;

    @Test
    void aReplayGivesAViewerWhatTheLiveRunGaveIt(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("run.rec");
        InJvmSimulation live = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .settings(s -> s.record(file)).run(300, false, Chatter::new);
        assertTrue(live.summary.completed(), live.summary.reason());
        try (ProcessLines replay = replay(file, "--speed", "100", "--exit-at-end")) {
            ViewerStream got = new ViewerStream();
            String watched = live.spec.robots().get(0).name(); // (as the live run's recording viewer watched it)
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", port(replay, "viewers"),
                    new ViewerHello(true, 0, watched), LONG_S * 1000, null);
            viewer.start(got);
            viewer.awaitEnd(LONG_S, TimeUnit.SECONDS);
            assertEquals(0, replay.exit(LONG_S), replay.output());

            assertArrayEquals(RecordingRunTest.bytes(live.snapshot), RecordingRunTest.bytes(got.snapshot()), "snapshot");
            List<PoseUpdate> updates = got.updates();
            assertEquals(live.updates.size(), updates.size(), "updates");
            for (int k = 0; k < updates.size(); k++) {
                assertArrayEquals(RecordingRunTest.bytes(live.updates.get(k)), RecordingRunTest.bytes(updates.get(k)),
                        "update " + k);
            }
            List<RobotView> views = got.views();
            assertEquals(live.views.size(), views.size(), "the watched robot's views");
            for (int k = 0; k < views.size(); k++) {
                assertArrayEquals(RecordingRunTest.bytes(live.views.get(k)), RecordingRunTest.bytes(views.get(k)),
                        "view " + k);
                assertTrue(got.messages.get(got.messages.indexOf(views.get(k)) - 1) == updates.get(k),
                        "view " + k + " right after its update");
            }
            assertArrayEquals(RecordingRunTest.bytes(live.end), RecordingRunTest.bytes(got.end()), "end");
            assertTrue(got.messages.get(got.messages.size() - 1) == got.end(), "the end comes last");
            // run states are the one thing a viewer's own timing shapes (a queue holds the newest only):
            // both streams say the run waited and then ran from step 0, however many of those they saw
            for (List<RunState> states : List.of(live.states, got.states())) {
                assertFalse(states.isEmpty(), "a run state after the snapshot");
                for (RunState s : states) {
                    assertEquals(0, s.step(), states.toString());
                    assertTrue(s.phase() != RunState.Phase.PAUSED, states.toString());
                }
                assertEquals(RunState.Phase.RUNNING, states.get(states.size() - 1).phase(), states.toString());
            }
        }
    }

    @Test
    void theControlPortSeeksStepsAndStopsAReplay(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("run.rec");
        InJvmSimulation live = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .settings(s -> s.record(file)).run(SEEK_STEPS, true, Chatter::new);
        assertTrue(live.summary.completed(), live.summary.reason());
        try (ProcessLines replay = replay(file, "--paused")) {
            ViewerStream got = new ViewerStream();
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", port(replay, "viewers"), new ViewerHello(false),
                    LONG_S * 1000, null);
            viewer.start(got);
            got.awaitSnapshot(LONG_S); // (it has joined: what the replay shows from now on reaches it)
            ViewerClient stranger = ViewerClient.connect("127.0.0.1", port(replay, "viewers"),
                    new ViewerHello(false, 0, "nobody"), LONG_S * 1000, null);
            stranger.start(new ViewerStream());
            assertEquals("it would watch \"nobody\", which is not a robot of this recording",
                    stranger.awaitEnd(LONG_S, TimeUnit.SECONDS).reason());
            try (ControlClient control = new ControlClient("127.0.0.1", port(replay, "control"), null, (int) (LONG_S * 1000))) {
                // steps as every display numbers them (steps completed): seek N shows the world after N steps,
                // the update of wire step N - 1, and the viewer's status line says step N (issue 31, item 5)
                assertEquals("at step " + MIDDLE, ok(control.request("seek " + MIDDLE)).path("message").asText());
                PoseUpdate sought = got.awaitStep(MIDDLE - 1, 0, LONG_S);
                assertArrayEquals(RecordingRunTest.bytes(live.updates.get(MIDDLE - 1)), RecordingRunTest.bytes(sought),
                        "the poses after " + MIDDLE + " steps");
                WorldSnapshot world = assertInstanceOf(WorldSnapshot.class, got.messages.get(got.messages.indexOf(sought) - 1),
                        "a seek: the world at the sought step right before its update (the viewer starts afresh there)");
                assertEquals(MIDDLE - 1, world.step());
                assertArrayEquals(RecordingRunTest.bytes(sought), RecordingRunTest.bytes(world.poses()), "the world's poses");
                SceneFeed shown = new SceneFeed(System::nanoTime);
                shown.snapshot(got.snapshot());
                shown.update(sought);
                assertTrue(StatusLine.text(shown.latest()).startsWith("step " + MIDDLE + " "), StatusLine.text(shown.latest()));
                int seen = got.messages.size();
                assertEquals("paused at step " + (MIDDLE + 1), ok(control.request("step 1")).path("message").asText());
                assertArrayEquals(RecordingRunTest.bytes(live.updates.get(MIDDLE)),
                        RecordingRunTest.bytes(got.awaitStep(MIDDLE, seen, LONG_S)), "then step " + (MIDDLE + 1));
                JsonNode status = ok(control.request("status"));
                assertEquals("PAUSED", status.path("state").asText(), status.toString());
                assertEquals(MIDDLE + 1, status.path("step").asLong(), status.toString());
                assertEquals(1, status.path("first_step").asLong(), status.toString());
                assertEquals(SEEK_STEPS, status.path("last_step").asLong(), status.toString());

                assertTrue(control.request("seek " + (SEEK_STEPS + 1)).path("error").asText().contains("not in the recording"));
                assertTrue(control.request("seek 0").path("error").asText().contains("steps 1 to " + SEEK_STEPS));
                assertTrue(control.request("speed 1000").path("error").asText().contains("0.1 to 100"));
                assertTrue(control.request("step -3").path("error").asText().contains("positive whole number"));
                seen = got.messages.size();
                assertEquals("at step " + SEEK_STEPS, ok(control.request("seek " + SEEK_STEPS)).path("message").asText());
                got.awaitStep(SEEK_STEPS - 1, seen, LONG_S);
                assertTrue(control.request("resume").path("error").asText().contains("at the end of the recording"));
                seen = got.messages.size();
                ok(control.request("seek 10"));
                seen = got.messages.indexOf(got.awaitStep(9, seen, LONG_S));
                ok(control.request("speed 100"));
                ok(control.request("resume"));
                got.awaitStep(10, SEEK_STEPS - 2, seen, LONG_S); // runs on from where it was sought (a live viewer gets the newest)
                ok(control.request("stop"));
            }
            viewer.awaitEnd(LONG_S, TimeUnit.SECONDS);
            assertTrue(got.end().reason().contains("stopped"), got.end().reason());
            assertEquals(0, replay.exit(LONG_S), replay.output());
        }
    }

    @Test
    void aFileThatIsNotARecordingIsRefusedInOneLine(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("notes.txt"), "not a recording\n");
        try (ProcessLines replay = replay(file)) {
            assertEquals(2, replay.exit(LONG_S));
            assertEquals("replay: " + file + ": not a RoboSim recording", replay.output().strip());
        }
    }

    @Test
    void theDefaultPortsTakenAReplayListensOnFreeOnesAndSaysWhich(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("run.rec");
        InJvmSimulation live = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .settings(s -> s.record(file)).run(20, false, Chatter::new);
        assertTrue(live.summary.completed(), live.summary.reason());
        // the default ports held, as a live run holds them (here, or by whatever holds them on this machine: taken all
        // the same): the one test that touches fixed ports, and only to find them taken
        List<java.net.ServerSocket> held = new ArrayList<>();
        for (int p : new int[] {robosim.protocol.Protocol.DEFAULT_VIEWER_PORT, robosim.protocol.Protocol.DEFAULT_CONTROL_PORT}) {
            try {
                held.add(new java.net.ServerSocket(p, 1, java.net.InetAddress.getLoopbackAddress()));
            } catch (java.net.BindException taken) {
                // held by another process of this machine: taken all the same
            }
        }
        List<String> command = new ArrayList<>(ProcessLines.java(List.of(), "robosim.environment.replay.ReplayMain",
                file.toString(), "--speed", "100", "--exit-at-end"));
        try (ProcessLines replay = new ProcessLines("replay", new ProcessBuilder(command))) {
            int viewers = port(replay, "viewers");
            assertTrue(viewers != robosim.protocol.Protocol.DEFAULT_VIEWER_PORT, "a free port: " + viewers);
            ViewerClient viewer = ViewerClient.connect("127.0.0.1", viewers, new ViewerHello(true, 0, ""),
                    LONG_S * 1000, null);
            ViewerStream got = new ViewerStream();
            viewer.start(got);
            viewer.awaitEnd(LONG_S, TimeUnit.SECONDS);
            assertEquals(0, replay.exit(LONG_S), replay.output());
            assertEquals(live.updates.size(), got.updates().size(), "the viewer on the free port saw every step");
            assertTrue(replay.output().contains("replay: the viewer port 3000 is taken; viewers connect to " + viewers
                    + " (--viewer-port to choose)"), replay.output());
            assertTrue(replay.output().contains("replay: the control port 8100 is taken; the control port is "),
                    replay.output());
        } finally {
            for (java.net.ServerSocket s : held) {
                s.close();
            }
        }
    }

    private static JsonNode ok(JsonNode reply) {
        assertTrue(reply.path("ok").asBoolean(), reply.toString());
        return reply;
    }

    static int port(ProcessLines replay, String which) throws InterruptedException {
        Map<String, String> ports = HeadlessRunner.fields(replay.await("listening viewers=", LONG_S));
        return Integer.parseInt(ports.get(which));
    }

    /** The replay in its own process, on this JDK, on free ports. */
    static ProcessLines replay(Path file, String... options) throws java.io.IOException {
        List<String> command = new ArrayList<>(ProcessLines.java(List.of(), "robosim.environment.replay.ReplayMain",
                file.toString(), "--viewer-port", "0", "--control-port", "0"));
        command.addAll(List.of(options));
        return new ProcessLines("replay", new ProcessBuilder(command));
    }
}
