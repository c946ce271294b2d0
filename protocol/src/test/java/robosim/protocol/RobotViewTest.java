package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The robot-specific viewer's message: what it carries, its wire size, how a live viewer's views merge. */
class RobotViewTest {
    @Test
    void robotViewCarriesTheRobotsStepAndMergesWhatASkippingViewerMissed() throws Exception {
        StepRequest q = new StepRequest(7, 40, -5, true, List.of(new CommEvent("spoofed", "b", "hi")),
                List.of("heat"), true);
        StepResponse a = new StepResponse(7, 40, -5, "wall", 1, 2, 3, new double[0],
                List.of(new CommEvent("b", "a", "yo")), List.of("speed limit"),
                List.of(new SensorReading("heat", new double[] {21.5})), "b");
        RobotView v = MessageRoundTripTest.roundTrip(RobotView.of(8, 0, "a", q, a));
        assertEquals(8, v.step());
        assertEquals(8, v.sinceStep());
        assertEquals(0, v.robot());
        assertEquals(40, v.moveMm());
        assertEquals(-5, v.turnDeg());
        assertTrue(v.askedSonar());
        assertTrue(v.askedTag());
        assertEquals("wall", v.contact());
        assertEquals("b", v.tagged());
        assertEquals(List.of(new CommEvent("a", "b", "hi")), v.sent(), "from is the robot's own name");
        assertEquals(List.of(new CommEvent("b", "a", "yo")), v.delivered());
        assertEquals(List.of("speed limit"), v.notices());
        assertEquals(List.of(new SensorReading("heat", new double[] {21.5})), v.readings());
        // a robot with nothing beyond its command: robot, move, turn, flags after the step fields
        StepResponse quiet = new StepResponse(7, 0, 0, "", 1, 2, 3, new double[0], List.of(), List.of());
        StepRequest idle = new StepRequest(7, 0, 0, false, List.of());
        assertEquals(9 + 8 + 8 + 4 + 4 + 8 + 8 + 1, MessageRoundTripTest.repeatedSize(RobotView.of(8, 1, "b", idle, quiet)));

        // a live viewer's queue merges views it has not sent: the newest step, every message since
        RobotView earlier = RobotView.of(5, 0, "a", q, a);
        RobotView merged = v.after(earlier);
        assertEquals(8, merged.step());
        assertEquals(5, merged.sinceStep());
        assertEquals(2, merged.delivered().size());
        assertEquals(List.of("speed limit", "speed limit"), merged.notices());
        assertEquals(0, merged.leftOut());
        assertSame(v, v.after(RobotView.of(5, 1, "b", idle, quiet)), "another robot's view");
        RobotView many = v;
        for (int k = 0; k < RobotView.MAX_LOG; k++) {
            many = RobotView.of(9 + k, 0, "a", q, a).after(many);
        }
        assertEquals(RobotView.MAX_LOG, many.delivered().size());
        assertEquals(3, many.leftOut(), "one each of sent, delivered and notices fell off the bound");
        assertEquals(8, many.sinceStep());
    }

    @Test
    void viewsOfAnotherTimelineAreNotMergedAndABadOneIsRefused() throws Exception {
        StepRequest q = new StepRequest(0, 0, 0, false, List.of(new CommEvent("", "b", "hi")));
        StepResponse r = new StepResponse(0, 0, 0, "", 0, 0, 0, new double[0], List.of(), List.of());
        RobotView later = RobotView.of(500, 0, "a", q, r);
        RobotView soughtBack = RobotView.of(100, 0, "a", q, r);
        assertSame(soughtBack, soughtBack.after(later), "a replay sought back: the newest view alone");
        assertSame(later, later.after(later), "not twice");

        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream o = new ObjectOutputStream(bytes)) {
            o.writeLong(5); // step
            o.writeLong(9); // since a later step
            o.writeInt(0);
        }
        ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()));
        ProtocolException e = assertThrows(ProtocolException.class, () -> new RobotView().readExternal(in));
        assertTrue(e.getMessage().contains("since step 9"), e.getMessage());
    }

    @Test
    void theRecordersWayOfWritingABodyIsByteForByteTheViews() throws Exception {
        StepRequest q = new StepRequest(7, 40, -5, true, List.of(new CommEvent("spoofed", "b", "hi")),
                List.of("heat"), true);
        StepResponse r = new StepResponse(7, 40, -5, "wall", 1, 2, 3, new double[0],
                List.of(new CommEvent("b", "a", "yo")), List.of("speed limit"),
                List.of(new SensorReading("heat", new double[] {21.5})), "b");
        StepResponse quiet = new StepResponse(7, 0, 0, "", 1, 2, 3, new double[0], List.of(), List.of());
        for (StepRequest request : java.util.Arrays.asList(q, null)) {
            for (StepResponse response : List.of(r, quiet)) {
                ByteArrayOutputStream direct = new ByteArrayOutputStream();
                try (ObjectOutputStream o = new ObjectOutputStream(direct)) {
                    RobotView.writeBody(o, 3, "a", request, response, true);
                }
                ByteArrayOutputStream viaView = new ByteArrayOutputStream();
                try (ObjectOutputStream o = new ObjectOutputStream(viaView)) {
                    RobotView.of(7, 3, "a", request, response).writeBody(o);
                }
                org.junit.jupiter.api.Assertions.assertArrayEquals(viaView.toByteArray(), direct.toByteArray());
            }
        }
    }

    @Test
    void aBodyWithoutReadingsReadsAsTheViewWithNone() throws Exception {
        StepResponse r = new StepResponse(7, 40, -5, "wall", 1, 2, 3, new double[0], List.of(), List.of(),
                List.of(new SensorReading("heat", new double[] {21.5})), "");
        ByteArrayOutputStream lean = new ByteArrayOutputStream();
        try (ObjectOutputStream o = new ObjectOutputStream(lean)) {
            RobotView.writeBody(o, 3, "a", null, r, false);
        }
        StepResponse without = new StepResponse(7, 40, -5, "wall", 1, 2, 3, new double[0], List.of(), List.of(),
                List.of(), "");
        ByteArrayOutputStream none = new ByteArrayOutputStream();
        try (ObjectOutputStream o = new ObjectOutputStream(none)) {
            RobotView.writeBody(o, 3, "a", null, without, true);
        }
        org.junit.jupiter.api.Assertions.assertArrayEquals(none.toByteArray(), lean.toByteArray());
    }
}
