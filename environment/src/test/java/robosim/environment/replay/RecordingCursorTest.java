package robosim.environment.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.Arena;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.RecordingWriter;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;

/** A replay follows the world of each step it shows: viewers get it again when robots joined, or a seek crosses a join. */
class RecordingCursorTest {
    private static PoseUpdate poses(long k, int n) {
        double[] v = new double[n];
        for (int i = 0; i < n; i++) {
            v[i] = 1000 * i + k;
        }
        return new PoseUpdate(k, v, v.clone(), new double[n]);
    }

    private static WorldSnapshot world(int n, long step) {
        List<String> names = List.of("a", "b", "c").subList(0, n);
        return new WorldSnapshot(500, new Arena(0, 0, 10_000, 10_000), List.of(), names,
                List.of(robosim.devices.RobotTypes.properties("Scout"), robosim.devices.RobotTypes.properties("Scout"), robosim.devices.RobotTypes.properties("Scout")).subList(0, n), poses(step, n));
    }

    @Test
    void aViewerJoiningOrASeekGetsTheWholeDrawingAsOfTheStepShown(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("drawn.rec");
        robosim.protocol.Traces.Log drawing = new robosim.protocol.Traces.Log();
        try (RecordingWriter w = new RecordingWriter(file)) {
            w.snapshot(world(1, -1));
            for (int k = 0; k < 8; k++) {
                if (k == 5) {
                    drawing.erase();
                }
                drawing.add("a", k, 0, 0xFF0000);
                w.step(poses(k, 1).withExperiment(List.of(), List.of(), List.of(), drawing.since(), drawing.whole(), new int[0]),
                        new StepRequest[1], new StepResponse[1]);
            }
            w.end(new SimulationEnd(7, "completed 8 steps"));
        }
        try (RecordingReader r = new RecordingReader(file)) {
            RecordingCursor at = new RecordingCursor(r);
            for (int i = 0; i < 4; i++) {
                at.show(i);
            }
            assertEquals(4, at.snapshot().poses().traces().points(), "steps 0 to 3 drew a point each");
            at.show(1); // (a seek back)
            assertEquals(2, at.snapshot().poses().traces().points());
            at.show(6); // (a seek on, across the erasure at step 5)
            robosim.protocol.Traces whole = at.snapshot().poses().traces();
            assertEquals(2, whole.points());
            assertEquals(5, whole.xMm(0));
            robosim.protocol.Traces next = at.show(7).traces();
            assertEquals(3, at.snapshot().poses().traces().points());
            assertEquals(1, next.points(), "the next step: its own piece");
            assertTrue(at.show(2).traces().fresh(), "a seek: the replay's drawing whole, afresh");
        }
    }

    @Test
    void aLongReplaySoughtBackPiecesItsDrawingFromTheNearestKept(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("long.rec");
        robosim.protocol.Traces.Log drawing = new robosim.protocol.Traces.Log();
        int steps = 3 * RecordingCursor.KEPT_EVERY;
        try (RecordingWriter w = new RecordingWriter(file)) {
            w.snapshot(world(1, -1));
            for (int k = 0; k < steps; k++) {
                drawing.add(k % 3 == 0 ? "a" : "b", k, 0, 0xFF0000);
                w.step(poses(k, 1).withExperiment(List.of(), List.of(), List.of(), drawing.since(), drawing.whole(),
                        new int[0]), new StepRequest[1], new StepResponse[1]);
            }
            w.end(new SimulationEnd(steps - 1, "done"));
        }
        try (RecordingReader r = new RecordingReader(file)) {
            RecordingCursor at = new RecordingCursor(r);
            for (int i = 0; i < steps; i++) {
                at.show(i);
            }
            for (int i : new int[] {2 * RecordingCursor.KEPT_EVERY + 7, 5, RecordingCursor.KEPT_EVERY, steps - 1}) {
                at.show(i);
                robosim.protocol.Traces whole = at.snapshot().poses().traces();
                assertEquals(i + 1, whole.points(), "step " + i + ": a point each step up to it");
                assertEquals(i, whole.xMm(i));
                assertEquals(i % 3 == 0 ? "a" : "b", whole.name(whole.traceOf(i)));
            }
        }
    }

    @Test
    void aWorldWithObjectsIsSoughtIntoWithItsScenery(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("objects.rec");
        robosim.protocol.WorldObject box = new robosim.protocol.WorldObject("box", robosim.protocol.WorldObject.Shape.BOX,
                300, 300, 500, 1, 0.5, false, false, 0x808080, 5000, 5000, 0);
        robosim.protocol.Scenery scenery = new robosim.protocol.Scenery(robosim.protocol.Floor.PLAIN, List.of(),
                List.of(box));
        try (RecordingWriter w = new RecordingWriter(file)) {
            PoseUpdate start = poses(-1, 1).withScene(new double[] {5000}, new double[] {5000}, new double[] {0}, null);
            w.snapshot(new WorldSnapshot(500, new Arena(0, 0, 10_000, 10_000), List.of(), List.of("a"),
                    List.of(robosim.devices.RobotTypes.properties("Scout")), start, scenery));
            for (int k = 0; k < 3; k++) {
                w.step(poses(k, 1).withScene(new double[] {5000}, new double[] {5000}, new double[] {0}, null),
                        new StepRequest[1], new StepResponse[1]);
            }
            w.end(new SimulationEnd(2, "completed 3 steps"));
        }
        try (RecordingReader r = new RecordingReader(file)) {
            RecordingCursor at = new RecordingCursor(r);
            at.show(2);
            assertEquals(List.of(box), at.snapshot().scenery().objects(), "the world sought into, its box with it");
        }
    }

    @Test
    void theWorldOfEachStepShownGoesToViewersWhenItChanges(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("joins.rec");
        try (RecordingWriter w = new RecordingWriter(file)) {
            w.snapshot(world(2, -1));
            for (int k = 0; k < 6; k++) {
                if (k == 3) {
                    w.roster(world(3, 2));
                }
                int n = k < 3 ? 2 : 3;
                w.step(poses(k, n), new StepRequest[n], new StepResponse[n]);
            }
            w.end(new SimulationEnd(5, "completed 6 steps"));
        }
        try (RecordingReader r = new RecordingReader(file)) {
            RecordingCursor at = new RecordingCursor(r);
            assertEquals(2, at.snapshot().robotNames().size(), "a viewer joining before the first step");
            for (int i = 0; i < 3; i++) {
                assertEquals(2, at.show(i).count());
                assertNull(at.takeWorldChange());
            }
            assertEquals(3, at.show(3).count());
            assertEquals(List.of("a", "b", "c"), at.takeWorldChange().robotNames(), "c joined: the world again");
            assertNull(at.takeWorldChange(), "once");
            assertEquals(3, at.show(4).count());
            assertNull(at.takeWorldChange());
            assertEquals(3, at.snapshot().robotNames().size(), "a viewer joining now gets the grown world");
            assertEquals(2, at.show(1).count(), "a seek back before the join");
            assertEquals(List.of("a", "b"), at.takeWorldChange().robotNames());
        }
    }
}
