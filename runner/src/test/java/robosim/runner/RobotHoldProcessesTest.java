package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.control.ControlClient;
import robosim.protocol.CommEvent;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.RobotView;
import robosim.protocol.StepRequest;

/**
 * {@code --on-robot-loss HOLD} over real processes: robot ring2's process is killed (SIGKILL) in step 100 of
 * a 300-step run, the world runs 100 steps without it, and a new process takes it over. It goes on from where
 * it stood; every message sent to it meanwhile reaches it once, in order; and every robot's pose at every step
 * equals a run in which ring2 sent what it sent and merely stood still for those 200 steps.
 */
class RobotHoldProcessesTest {
    private static final long LONG_S = 50;
    /** The step in which ring2's process is killed. */
    private static final int LOSS = 100;
    /** The steps the world runs without it (LOSS + 1 to LOSS + AWAY); it is back in step BACK. */
    private static final int AWAY = 100;
    private static final int BACK = LOSS + AWAY + 1;
    private static final int STEPS = 300;
    private static final int RING2 = 1;
    private static final Path WORLD = Path.of("src/test/resources/ring-hold.xml");

    private static ProcessLines java(String name, String... args) throws Exception {
        return new ProcessLines(name, new ProcessBuilder(ProcessLines.java(List.of(), args[0],
                java.util.Arrays.copyOfRange(args, 1, args.length))));
    }

    private static ProcessLines environment(Path record, String... more) throws Exception {
        List<String> args = new ArrayList<>(List.of("robosim.environment.EnvironmentMain", WORLD.toString(), "--steps",
                Integer.toString(STEPS), "--no-geometry", "--robot-port", "0", "--viewer-port", "0", "--control-port",
                "0", "--record", record.toString()));
        args.addAll(List.of(more));
        return java("environment", args.toArray(String[]::new));
    }

    private static ProcessLines others(int port) throws Exception {
        return java("ring1,3,4", "robosim.hardware.MultiRobotMain", "127.0.0.1", Integer.toString(port), "--robot",
                "ring1:ArRobot:robosim.examples.RingChatter", "--robot", "ring3:ArRobot:robosim.examples.RingChatter",
                "--robot", "ring4:ArRobot:robosim.examples.RingChatter");
    }

    private static ProcessLines ring2(int port) throws Exception {
        return java("ring2", "robosim.hardware.RobotMain", "robosim.examples.RingChatter", "ring2", "127.0.0.1",
                Integer.toString(port), "--type", "ArRobot");
    }

    @Test
    void aRobotKilledMidRunComesBackWhereItStoodWithItsMessagesAndTheOthersMoveAsIfItHadStoodStill(
            @TempDir Path dir) throws Exception {
        Path held = dir.resolve("held.rec");
        try (ProcessLines env = environment(held, "--start-paused", "--on-robot-loss", "HOLD")) {
            Map<String, String> ports = HeadlessRunner.fields(env.await("listening robots=", LONG_S));
            int port = Integer.parseInt(ports.get("robots"));
            try (ProcessLines others = others(port); ProcessLines first = ring2(port);
                    ControlClient control = new ControlClient("127.0.0.1", Integer.parseInt(ports.get("control")), null,
                            (int) TimeUnit.SECONDS.toMillis(LONG_S))) {
                env.await("running robots=4", LONG_S);
                assertEquals("paused at step " + LOSS, ControlFixture.ok(control, "step " + LOSS));
                ControlFixture.ok(control, "pause"); // returns once step LOSS is computed: every request of it is in
                first.process.destroyForcibly();
                assertTrue(first.process.waitFor(LONG_S, TimeUnit.SECONDS));
                env.await("robot ring2 lost during step " + (LOSS + 1), LONG_S); // (the step after the LOSS done)
                ControlFixture.ok(control, "step 1");
                env.await("robot ring2 lost at step " + (LOSS + 2), LONG_S);
                assertEquals("held", state(control, "ring2"));
                ControlFixture.ok(control, "step " + (AWAY - 1));
                ControlFixture.ok(control, "pause"); // step LOSS + AWAY computed without it
                try (ProcessLines again = ring2(port)) {
                    env.await("robot ring2 says hello again", LONG_S);
                    assertEquals("returning", state(control, "ring2"));
                    ControlFixture.ok(control, "resume");
                    env.await("robot ring2 is back at step " + (BACK + 1), LONG_S);
                    env.await("summary steps=" + STEPS, LONG_S);
                    assertTrue(again.process.waitFor(LONG_S, TimeUnit.SECONDS));
                    assertTrue(others.process.waitFor(LONG_S, TimeUnit.SECONDS));
                }
            }
            assertTrue(env.process.waitFor(LONG_S, TimeUnit.SECONDS));
            assertEquals(0, env.process.exitValue(), env.output());
        }
        List<RecordingReader.Step> withHold = read(held);
        checkHeld(withHold);
        checkMessages(withHold);

        Path still = dir.resolve("still.rec");
        try (ProcessLines env = environment(still)) {
            int port = Integer.parseInt(HeadlessRunner.fields(env.await("listening robots=", LONG_S)).get("robots"));
            try (ProcessLines others = others(port); RawRobot ring2 = new RawRobot("ring2", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertTrue(ring2.welcome.isAccepted(), ring2.welcome.reason());
                while (ring2.next()) {
                    RobotView v = withHold.get((int) ring2.step).view(RING2);
                    ring2.connection.write(v == null ? new StepRequest(ring2.step, 0, 0, false, List.of())
                            : new StepRequest(ring2.step, v.moveMm(), v.turnDeg(), v.askedSonar(), v.sent(), List.of(),
                                    v.askedTag()));
                    ring2.connection.flush();
                    ring2.connection.read(robosim.protocol.StepResponse.class);
                }
                assertTrue(others.process.waitFor(LONG_S, TimeUnit.SECONDS));
            }
            assertTrue(env.process.waitFor(LONG_S, TimeUnit.SECONDS));
        }
        List<RecordingReader.Step> stoodStill = read(still);
        assertEquals(STEPS, stoodStill.size());
        for (int k = 0; k < STEPS; k++) {
            PoseUpdate a = withHold.get(k).update();
            PoseUpdate b = stoodStill.get(k).update();
            for (int i = 0; i < a.count(); i++) {
                String at = "robot " + i + " at step " + k;
                assertEquals(b.xMm(i), a.xMm(i), at);
                assertEquals(b.yMm(i), a.yMm(i), at);
                assertEquals(b.headingDeg(i), a.headingDeg(i), at);
            }
        }
    }

    private static List<RecordingReader.Step> read(Path file) throws Exception {
        try (RecordingReader r = new RecordingReader(file)) {
            assertNull(r.cutShort(), file + " is whole");
            List<RecordingReader.Step> steps = new ArrayList<>();
            for (int i = 0; i < r.steps(); i++) {
                steps.add(r.step(i));
                assertEquals(i, steps.get(i).update().step());
            }
            assertEquals(STEPS, steps.size());
            return steps;
        }
    }

    /** ring2 took part in step LOSS (nothing reached it), stood where it was from LOSS + 1 to LOSS + AWAY, moved on from BACK. */
    private static void checkHeld(List<RecordingReader.Step> steps) {
        PoseUpdate atLoss = steps.get(LOSS).update();
        for (int k = LOSS + 1; k <= LOSS + AWAY; k++) {
            PoseUpdate u = steps.get(k).update();
            assertEquals(atLoss.xMm(RING2), u.xMm(RING2), "step " + k);
            assertEquals(atLoss.yMm(RING2), u.yMm(RING2), "step " + k);
            assertEquals(atLoss.headingDeg(RING2), u.headingDeg(RING2), "step " + k);
            assertNull(steps.get(k).view(RING2), "no view of an away robot, step " + k);
            assertEquals(List.of("ring2"), u.held(), "viewers see it held, step " + k);
        }
        assertEquals(List.of(), steps.get(LOSS).update().held());
        assertEquals(List.of(), steps.get(BACK).update().held(), "viewers see it back");
        boolean bumped = false;
        for (int k = LOSS + 1; k <= LOSS + AWAY; k++) {
            for (int i = 0; i < steps.get(k).update().count(); i++) {
                RobotView v = steps.get(k).view(i);
                bumped |= i != RING2 && v != null && v.contact().equals("ring2");
            }
        }
        assertTrue(bumped, "another robot ran into ring2 where it stood (the world tests what it should)");
        assertNotNull(steps.get(LOSS).view(RING2));
        assertEquals(List.of(), steps.get(LOSS).view(RING2).delivered(), "step " + LOSS + "'s response never reached it");
        assertNotNull(steps.get(BACK).view(RING2), "back at step " + BACK);
        assertTrue(steps.get(BACK).view(RING2).moveMm() != 0 || steps.get(BACK).view(RING2).turnDeg() != 0,
                "its new process drives it");
    }

    /** What ring1 sent ring2 reached it once, in order; what was sent from step LOSS to BACK in its first response back. */
    private static void checkMessages(List<RecordingReader.Step> steps) {
        List<String> sent = new ArrayList<>();
        List<String> delivered = new ArrayList<>();
        List<String> whileAway = new ArrayList<>();
        for (int k = 0; k < STEPS; k++) {
            for (CommEvent m : steps.get(k).view(0).sent()) {
                if (m.to().equals("ring2")) {
                    sent.add(m.payload());
                    if (k >= LOSS && k <= BACK) {
                        whileAway.add(m.payload());
                    }
                }
            }
            RobotView v = steps.get(k).view(RING2);
            if (v != null) {
                v.delivered().forEach(m -> delivered.add(m.from() + ":" + m.payload()));
            }
        }
        assertEquals(STEPS, sent.size(), "ring1 sends ring2 one message a step");
        assertEquals(sent.stream().map(p -> "ring1:" + p).toList(), delivered);
        assertEquals(whileAway.stream().map(p -> "ring1:" + p).toList(),
                steps.get(BACK).view(RING2).delivered().stream().map(m -> m.from() + ":" + m.payload()).toList());
    }

    private static String state(ControlClient control, String robot) throws Exception {
        for (JsonNode r : control.request("robots").path("robots")) {
            if (r.path("name").asText().equals(robot)) {
                return r.path("state").asText();
            }
        }
        throw new AssertionError("no robot " + robot + " in the robots list");
    }
}
