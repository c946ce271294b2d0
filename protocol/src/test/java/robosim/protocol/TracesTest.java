package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import org.junit.jupiter.api.Test;

/**
 * A drawing of loop functions: pieces drawn step by step, carried over the wire and pieced together again by a viewer
 * give the drawing drawn; a viewer's queue that keeps only the newest update sends the pieces it dropped joined to
 * it; a snapshot's whole drawing followed by its step's piece draws each point once; pieces out of bounds or that
 * would leave a gap are refused.
 */
class TracesTest {
    private static Traces wire(Traces piece) throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            piece.write(out);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            return Traces.read(in);
        }
    }

    private static String drawn(Traces.Log log) {
        Traces all = log.whole();
        StringBuilder s = new StringBuilder();
        for (int p = 0; p < all.points(); p++) {
            s.append(all.name(all.traceOf(p))).append('#').append(Integer.toHexString(all.rgb(all.traceOf(p))))
                    .append('(').append(all.xMm(p)).append(',').append(all.yMm(p)).append(") ");
        }
        return s.toString().trim();
    }

    @Test
    void piecesOverTheWireDrawWhatWasDrawnAndMergedPiecesDrawTheSame() throws Exception {
        Traces.Log source = new Traces.Log();
        Traces.Log viewer = new Traces.Log();
        Traces.Log merged = new Traces.Log();
        Traces held = Traces.NONE;
        for (int step = 0; step < 40; step++) { // (enough points that the source's arrays grow, pieces kept meanwhile)
            source.add("fb" + step % 3, step, -step, 0x00FF00 + step % 3);
            if (step % 7 == 0) {
                source.add("extra", step, step, 0xFF0000);
            }
            Traces piece = source.since();
            viewer.apply(wire(piece));
            held = held.then(step % 2 == 0 ? piece : wire(piece)); // (a replay's queue joins pieces read back too)
            if (step % 5 == 4) { // (a viewer sent the newest of five updates: what the five drew)
                merged.apply(wire(held));
                held = Traces.NONE;
            }
        }
        assertEquals(drawn(source), drawn(viewer));
        assertEquals(drawn(source), drawn(merged));
        assertEquals("fb0#ff00(0.0,0.0) extra#ff0000(0.0,0.0) fb1#ff01(1.0,-1.0)",
                drawn(viewer).substring(0, drawn(viewer).indexOf(" fb2")));
        assertTrue(source.since().isEmpty(), "nothing drawn since");
    }

    @Test
    void aSnapshotsWholeDrawingThenItsStepsPieceDrawsEachPointOnce() throws Exception {
        Traces.Log source = new Traces.Log();
        source.add("a", 1, 1, 0);
        source.since();
        source.add("a", 2, 2, 0);
        source.add("b", 3, 3, 0);
        Traces piece = source.since();
        Traces.Log joiner = new Traces.Log();
        joiner.apply(wire(source.whole()));
        joiner.apply(wire(piece)); // (held already: skipped)
        assertEquals(drawn(source), drawn(joiner));
        source.erase();
        source.add("c", 4, 4, 0x123456);
        Traces fresh = source.since();
        assertTrue(fresh.fresh());
        joiner.apply(wire(fresh));
        assertEquals("c#123456(4.0,4.0)", drawn(joiner));
    }

    @Test
    void whatCannotBeDrawnIsRefused() throws Exception {
        Traces.Log log = new Traces.Log();
        assertThrows(IllegalArgumentException.class, () -> log.add("", 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> log.add("x".repeat(Traces.MAX_NAME + 1), 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> log.add("a", Double.NaN, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> log.add("a", 0, 0, 0x1000000));
        for (int t = 0; t < Traces.MAX_TRACES; t++) {
            log.add("t" + t, 0, 0, 0);
        }
        assertEquals("a drawing holds at most 1024 traces: erase first",
                assertThrows(IllegalStateException.class, () -> log.add("one more", 0, 0, 0)).getMessage());
        log.add("t0", 1, 1, 0); // (a trace there is takes points still)
        Traces.Log other = new Traces.Log();
        other.add("a", 0, 0, 0);
        other.since();
        other.add("a", 1, 1, 0);
        Traces later = other.since();
        Traces.Log empty = new Traces.Log();
        assertThrows(ProtocolException.class, () -> empty.apply(wire(later)), "a gap");
        assertFalse(later.fresh());
    }

    @Test
    void aPieceOnTheWireIsCheckedAsItIsRead() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeBoolean(false);
            out.writeInt(0);
            out.writeInt(1);
            out.writeUTF("a");
            out.writeInt(0);
            out.writeInt(0);
            out.writeInt(1);
            out.writeShort(3); // (a point of trace 3 in a drawing of one)
            out.writeDouble(0);
            out.writeDouble(0);
        }
        ProtocolException e = assertThrows(ProtocolException.class, () -> Traces.read(new ObjectInputStream(
                new ByteArrayInputStream(bytes.toByteArray()))));
        assertEquals("point 0 of trace 3 (of 1) at (0.0, 0.0)", e.getMessage());
        ByteArrayOutputStream many = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(many)) {
            out.writeBoolean(false);
            out.writeInt(0);
            out.writeInt(Traces.MAX_TRACES + 1);
        }
        assertThrows(ProtocolException.class, () -> Traces.read(new ObjectInputStream(
                new ByteArrayInputStream(many.toByteArray()))));
    }
}
