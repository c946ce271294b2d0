package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A recording reads back as written, and a file cut at any byte (a writer killed at any moment) reads
 * up to its last whole frame, saying where it stops.
 */
class RecordingTest {
    /** Two robots' properties (the devices module's ArRobot and Scout, which this module does not see). */
    private static final RobotProperties AR_ROBOT = new RobotProperties("ArRobot", 250, 1000, 300,
            List.of(SonarSpec.onRim(250, 0, 15, 5000)));
    private static final RobotProperties SCOUT = new RobotProperties("Scout", 190, 1000, 300,
            List.of(SonarSpec.onRim(190, 0, 22.5, 5000), SonarSpec.onRim(190, 180, 22.5, 5000)));

    private static final List<String> NAMES = List.of("a", "b");

    private static PoseUpdate update(long k) {
        return new PoseUpdate(k, new double[] {k, 2 * k}, new double[] {1, 2}, new double[] {0, 90},
                new double[][] {{100 + k, 200}, {}}, List.of("a>b"), k > 5 ? List.of("b") : List.of());
    }

    private static StepRequest[] requests(long k) {
        StepRequest a = new StepRequest(k, 40, -5, true, List.of(new CommEvent("", "b", "hi " + k)),
                List.of("laser"), k % 2 == 0);
        return new StepRequest[] {a, null};
    }

    private static StepResponse[] responses(long k) {
        StepResponse a = new StepResponse(k, 0, 0, k % 3 == 0 ? "arena" : "", k, 1, 0, new double[0],
                List.of(new CommEvent("b", "a", "hello " + k)), List.of(),
                List.of(new SensorReading("laser", new double[] {1.5, k})));
        return new StepResponse[] {a, null};
    }

    /** Writes steps 0..n-1 (and the end if asked); returns each frame's end offset, the header's first. */
    private static List<Long> write(Path file, int n, boolean end) throws IOException {
        List<Long> ends = new ArrayList<>();
        try (RecordingWriter w = new RecordingWriter(file)) {
            w.snapshot(new WorldSnapshot(500, new Arena(0, 0, 1000, 1000), List.of(), NAMES,
                    List.of(AR_ROBOT, SCOUT), update(0)));
            w.flush();
            ends.add(Files.size(file));
            for (int k = 0; k < n; k++) {
                w.step(update(k), requests(k), responses(k));
                w.flush();
                ends.add(Files.size(file));
            }
            if (end) {
                w.end(new SimulationEnd(n - 1, "completed " + n + " steps"));
            }
        }
        return ends;
    }

    /**
     * A version 4 recording (written by RoboSim before worlds had scenery: {@code v4.rec}, a snapshot of robots a and b
     * and one step) reads without scenery, objects, LEDs or anything of loop functions (as version 5 does); as version 3 (the same bytes: its views hold nothing
     * more) without reports; version 2 is refused.
     */
    @Test
    void olderRecordingsReadAsTheyWereWrittenAndVersionTwoIsRefused(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("v4.rec");
        byte[] bytes = getClass().getResourceAsStream("/v4.rec").readAllBytes();
        Files.write(file, bytes);
        try (RecordingReader r = new RecordingReader(file)) {
            assertEquals(NAMES, r.snapshot().robotNames());
            assertEquals(Scenery.NONE, r.snapshot().scenery());
            assertEquals(AR_ROBOT, r.snapshot().robots().get(0));
            assertEquals(1, r.steps());
            assertEquals(0, r.step(0).update().objectCount());
            assertEquals(0, r.step(0).update().leds(0).length);
            assertEquals(2, r.step(0).update().yMm(1));
            assertEquals(List.of(), r.step(0).update().paint());
            assertEquals(List.of(), r.step(0).update().reports());
        }
        bytes[RecordingFormat.MAGIC.length] = 3;
        Files.write(file, bytes);
        try (RecordingReader r = new RecordingReader(file)) {
            assertEquals(1, r.steps());
            assertEquals(List.of(), r.step(0).views().get(0).reports());
        }
        bytes[RecordingFormat.MAGIC.length] = 2;
        Files.write(file, bytes);
        IOException e = assertThrows(IOException.class, () -> new RecordingReader(file));
        assertEquals(file + ": recording version 2, this RoboSim reads " + RecordingFormat.VERSION, e.getMessage());
    }

    @Test
    void aRecordingReadsBackAsWritten(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("run.rec");
        write(file, 10, true);
        try (RecordingReader r = new RecordingReader(file)) {
            assertEquals(NAMES, r.snapshot().robotNames());
            assertEquals(10, r.steps());
            assertEquals("completed 10 steps", r.end().reason());
            assertNull(r.cutShort());
            for (int k = 0; k < 10; k++) {
                RecordingReader.Step s = r.step(k);
                PoseUpdate want = update(k);
                assertEquals(k, s.update().step());
                assertEquals(want.xMm(1), s.update().xMm(1));
                assertArrayEquals(want.sonarMm(0), s.update().sonarMm(0));
                assertEquals(want.departed(), s.update().departed());
                assertEquals(1, s.views().size(), "robot b was not in the step");
                assertNull(s.view(1));
                RobotView e = s.view(0);
                assertEquals(0, e.robot());
                assertEquals(k, e.step());
                assertEquals(k, e.sinceStep());
                assertEquals(40, e.moveMm());
                assertEquals(-5, e.turnDeg());
                assertTrue(e.askedSonar());
                assertEquals(k % 2 == 0, e.askedTag());
                assertEquals(k % 3 == 0 ? "arena" : "", e.contact());
                assertEquals(List.of(new CommEvent("a", "b", "hi " + k)), e.sent(), "its outbox, from its name");
                assertEquals(List.of(new CommEvent("b", "a", "hello " + k)), e.delivered());
                assertEquals(List.of(new SensorReading("laser", new double[] {1.5, k})), e.readings());
            }
        }
    }

    @Test
    void robotsThatJoinAreInTheWorldOfEveryStepAfterThem(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("joins.rec");
        Arena arena = new Arena(0, 0, 1000, 1000);
        WorldSnapshot three = new WorldSnapshot(500, arena, List.of(), List.of("a", "b", "c"),
                List.of(AR_ROBOT, SCOUT, SCOUT), update3(2));
        try (RecordingWriter w = new RecordingWriter(file)) {
            w.snapshot(new WorldSnapshot(500, arena, List.of(), NAMES, List.of(AR_ROBOT, SCOUT),
                    update(0)));
            for (int k = 0; k < 3; k++) {
                w.step(update(k), requests(k), responses(k));
            }
            w.roster(three);
            for (int k = 3; k < 5; k++) {
                StepResponse c = new StepResponse(k, 0, 0, "", 5, 5, 0, new double[0],
                        List.of(new CommEvent("a", "c", "welcome " + k)), List.of());
                w.step(update3(k), new StepRequest[] {null, null, new StepRequest(k, 10, 0, false, List.of())},
                        new StepResponse[] {null, null, c});
            }
            w.end(new SimulationEnd(4, "completed 5 steps"));
        }
        try (RecordingReader r = new RecordingReader(file)) {
            assertEquals(5, r.steps());
            assertNull(r.cutShort());
            assertEquals(NAMES, r.snapshotAt(2).robotNames());
            assertEquals(List.of("a", "b", "c"), r.snapshotAt(3).robotNames());
            assertEquals(List.of("a", "b", "c"), r.snapshotAt(4).robotNames());
            assertEquals(3, r.step(4).update().count());
            assertEquals(List.of(new CommEvent("a", "c", "welcome 4")), r.step(4).view(2).delivered(),
                    "the joined robot's view names it");
            assertEquals(2, r.step(2).update().count());
        }
    }

    private static PoseUpdate update3(long k) {
        return new PoseUpdate(k, new double[] {k, 2 * k, 5}, new double[] {1, 2, 5}, new double[] {0, 90, 0});
    }

    @Test
    void aFileCutAtAnyByteReadsUpToItsLastWholeFrame(@TempDir Path dir) throws IOException {
        Path whole = dir.resolve("whole.rec");
        List<Long> ends = write(whole, 4, false);
        byte[] bytes = Files.readAllBytes(whole);
        Path cut = dir.resolve("cut.rec");
        for (int length = (int) (long) ends.get(0); length <= bytes.length; length++) {
            Files.write(cut, Arrays.copyOf(bytes, length));
            int whole_frames = 0;
            for (int k = 1; k < ends.size(); k++) {
                whole_frames += ends.get(k) <= length ? 1 : 0;
            }
            try (RecordingReader r = new RecordingReader(cut)) {
                assertEquals(whole_frames, r.steps(), "cut at byte " + length);
                assertNull(r.end());
                boolean atAFrameEnd = ends.contains((long) length);
                assertEquals(atAFrameEnd, r.cutShort() == null, "cut at byte " + length + ": " + r.cutShort());
                for (int k = 0; k < r.steps(); k++) {
                    assertEquals(k, r.step(k).update().step());
                }
            }
        }
        // cut inside the snapshot: not a recording yet, said in one line naming the file
        Files.write(cut, Arrays.copyOf(bytes, (int) (long) ends.get(0) - 1));
        IOException e = assertThrows(IOException.class, () -> new RecordingReader(cut).close());
        assertTrue(e.getMessage().startsWith(cut + ": no snapshot at the start"), e.getMessage());
    }

    @Test
    void aDamagedFrameEndsTheReadingThere(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("run.rec");
        List<Long> ends = write(file, 5, true);
        byte[] bytes = Files.readAllBytes(file);
        bytes[(int) (long) ends.get(2) + 20] ^= 0x40; // inside the third step's frame
        Files.write(file, bytes);
        try (RecordingReader r = new RecordingReader(file)) {
            assertEquals(2, r.steps(), "the steps before the damaged frame");
            assertNotNull(r.step(1));
            assertNull(r.end());
            assertEquals("a frame failing its checksum at byte " + ends.get(2), r.cutShort());
        }
        Files.write(file, "not a recording at all".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        IOException e = assertThrows(IOException.class, () -> new RecordingReader(file).close());
        assertEquals(file + ": not a RoboSim recording", e.getMessage());
    }
}
