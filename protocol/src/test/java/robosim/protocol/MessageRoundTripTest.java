package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.Externalizable;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Every message survives a round trip through object streams, and its wire size is exactly its
 * payload plus the 9 bytes an already-described Externalizable object costs: TC_OBJECT, a handle
 * to its class descriptor (1 + 4), a short block-data header (2) and TC_ENDBLOCKDATA.
 */
class MessageRoundTripTest {
    private static final int OVERHEAD = 9;

    static final RobotProperties PROPS = new RobotProperties("ArRobot", 250, 500, 90,
            List.of(new SonarSpec(100, 0, 0, 15, 5000)));

    /** Writes the message twice in one stream and returns the bytes of the second copy. */
    static int repeatedSize(Externalizable m) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ObjectOutputStream out = new ObjectOutputStream(bytes);
        out.writeUnshared(m);
        out.flush();
        int first = bytes.size();
        out.writeUnshared(m);
        out.flush();
        return bytes.size() - first;
    }

    @SuppressWarnings("unchecked")
    static <T extends Externalizable> T roundTrip(T m) throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeUnshared(m);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            in.setObjectInputFilter(new ProtocolFilter());
            return (T) in.readUnshared();
        }
    }

    /**
     * Wire bytes of a repeated message with this payload: a payload over 255 bytes (and up to the
     * 1024-byte block size) takes the long block-data header, 5 bytes instead of 2.
     */
    private static int wire(int payload) {
        return payload + (payload > 255 ? OVERHEAD + 3 : OVERHEAD);
    }

    private static int utf(String s) {
        return 2 + s.length();
    }

    @Test
    void robotHello() throws Exception {
        RobotHello m = roundTrip(new RobotHello("robot1", PROPS));
        assertEquals(Protocol.VERSION, m.protocolVersion());
        assertEquals("robot1", m.name());
        assertEquals(PROPS, m.properties());
        int props = utf("ArRobot") + 5 * 8 + 4 + 5 * 8 + 4 + 4 + 1; // (no rays, no LEDs, no gripper)
        assertEquals(OVERHEAD + 4 + utf("robot1") + 1 + props, repeatedSize(new RobotHello("robot1", PROPS)));
        RobotHello any = roundTrip(RobotHello.anyType("robot1"));
        assertTrue(any.anyType());
        assertNull(any.properties());
        assertEquals(OVERHEAD + 4 + utf("robot1") + 1, repeatedSize(RobotHello.anyType("robot1")));
    }

    @Test
    void robotWelcomeAcceptedAndRefused() throws Exception {
        RobotWelcome m = roundTrip(RobotWelcome.accepted(500, 1000, 2000, 90, List.of("a", "b")));
        assertTrue(m.isAccepted());
        assertEquals(500, m.timeStepMs());
        assertEquals(1000, m.xMm());
        assertEquals(2000, m.yMm());
        assertEquals(90, m.headingDeg());
        assertEquals(List.of("a", "b"), m.robotNames());
        assertTrue(m.stepMessages());
        assertFalse(roundTrip(RobotWelcome.accepted(500, 0, 0, 0, List.of()).withStepMessages(false)).stepMessages());
        assertEquals(OVERHEAD + 1 + utf("") + 8 + 3 * 8 + 4 + utf("a") + utf("b") + 4 + utf("laser") + 1 + 8 + 4
                + utf("Scout") + 4, repeatedSize(RobotWelcome.accepted(500, 1000, 2000, 90, List.of("a", "b"),
                        List.of("laser")).withType("Scout")));
        assertEquals("Scout", roundTrip(RobotWelcome.accepted(500, 0, 0, 0, List.of()).withType("Scout")).type());
        RobotWelcome run = roundTrip(RobotWelcome.accepted(500, 0, 0, 0, List.of())
                .withRun(42, java.util.Map.of("speed", "300")));
        assertEquals(42, run.seed());
        assertEquals(java.util.Map.of("speed", "300"), run.parameters());
        assertEquals(List.of("laser"),
                roundTrip(RobotWelcome.accepted(500, 0, 0, 0, List.of(), List.of("laser"))).sensors());

        RobotWelcome r = roundTrip(RobotWelcome.refused("no robot named x"));
        assertFalse(r.isAccepted());
        assertEquals("no robot named x", r.reason());
    }

    @Test
    void aReportWithABadNameOrValueIsRefusedOnEitherSide() throws Exception {
        assertThrows(IllegalArgumentException.class, () -> new Report("two words", 1));
        assertThrows(IllegalArgumentException.class, () -> new Report("x", Double.NaN));
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        try (java.io.ObjectOutputStream out = new java.io.ObjectOutputStream(bytes)) {
            out.writeShort(1);
            out.writeUTF("line\nbreak");
            out.writeDouble(1);
        }
        try (java.io.ObjectInputStream in = new java.io.ObjectInputStream(
                new java.io.ByteArrayInputStream(bytes.toByteArray()))) {
            ProtocolException e = assertThrows(ProtocolException.class, () -> Report.read(in, Report.MAX_PER_STEP));
            assertTrue(e.getMessage().contains("line?break"), e.getMessage());
        }
    }

    @Test
    void stepRequest() throws Exception {
        StepRequest m = roundTrip(new StepRequest(7, 250, -45, true, List.of(new CommEvent("", "robot2", "7"))));
        assertEquals(7, m.step());
        assertEquals(250, m.moveMm());
        assertEquals(-45, m.turnDeg());
        assertTrue(m.wantsSonar());
        assertEquals(List.of(new CommEvent("", "robot2", "7")), m.messages());
        // (no actuations, the gripper staying: a count and a byte)
        assertEquals(OVERHEAD + 8 + 8 + 8 + 1 + 4 + 4 + 1 + 2 + 1 + 1,
                repeatedSize(new StepRequest(7, 250, 0, false, List.of())));
        StepRequest reported = roundTrip(new StepRequest(1, 0, 0, false, List.of(), List.of(), false,
                List.of(new Report("found", 3), new Report("t.goal-1", 0.5))));
        assertEquals(List.of(new Report("found", 3), new Report("t.goal-1", 0.5)), reported.reports());
        assertTrue(roundTrip(new StepRequest(1, 0, 0, false, List.of(), List.of(), true)).wantsTag());
        StepRequest withSensors = roundTrip(new StepRequest(1, 0, 0, false, List.of(), List.of("laser", "heat")));
        assertEquals(List.of("laser", "heat"), withSensors.sensors());
    }

    @Test
    void stepResponse() throws Exception {
        double[] ranges = {1000, 2000.5};
        StepResponse m = roundTrip(new StepResponse(3, 240, 0, "wall", 1, 2, 3, ranges,
                List.of(new CommEvent("robot2", "robot1", "hi")), List.of("note")));
        assertEquals(3, m.step());
        assertEquals(240, m.movedMm());
        assertEquals("wall", m.contact());
        assertEquals(1, m.xMm());
        assertEquals(2, m.yMm());
        assertEquals(3, m.headingDeg());
        assertArrayEquals(ranges, m.sonarMm());
        assertEquals(List.of(new CommEvent("robot2", "robot1", "hi")), m.inbox());
        assertEquals(List.of("note"), m.notices());
        StepResponse empty = new StepResponse(3, 250, 0, "", 1, 2, 3, new double[0], List.of(), List.of());
        assertEquals(OVERHEAD + 8 + 8 + 8 + utf("") + 3 * 8 + 4 + 4 + 4 + 4 + utf("") + utf(""), repeatedSize(empty));
        assertEquals("robot2", roundTrip(new StepResponse(3, 0, 0, "", 1, 2, 3, new double[0], List.of(), List.of(),
                List.of(), "robot2")).tagged());
        StepResponse withReading = new StepResponse(3, 250, 0, "", 1, 2, 3, new double[0], List.of(), List.of(),
                List.of(new SensorReading("heat", new double[] {0.5})));
        assertEquals(List.of(new SensorReading("heat", new double[] {0.5})), roundTrip(withReading).readings());
        assertEquals(OVERHEAD + 8 + 8 + 8 + utf("") + 3 * 8 + 4 + 4 + 4 + 4 + utf("heat") + 4 + 8 + utf("") + utf(""),
                repeatedSize(withReading));
    }

    @Test
    void geometryHelloAndWorld() throws Exception {
        assertEquals(Protocol.VERSION, roundTrip(new GeometryHello()).protocolVersion());
        assertEquals(OVERHEAD + 4, repeatedSize(new GeometryHello()));

        Arena arena = new Arena(0, 0, 10_000, 5_000);
        ObstacleShape box = ObstacleShape.rectangle("box", 1000, 1000, 500, 500);
        GeometryWorld m = roundTrip(new GeometryWorld(arena, List.of(box), List.of("r1"), List.of(PROPS)));
        assertEquals(arena, m.arena());
        assertEquals(List.of(box), m.obstacles());
        assertEquals(List.of("r1"), m.robotNames());
        assertEquals(List.of(PROPS), m.robots());
        int props = utf("ArRobot") + 5 * 8 + 4 + 5 * 8 + 4 + 4 + 1; // (no rays, no LEDs, no gripper)
        assertEquals(OVERHEAD + 4 * 8 + 4 + utf("box") + 4 + 8 * 8 + 4 + utf("r1") + props + 4,
                repeatedSize(new GeometryWorld(arena, List.of(box), List.of("r1"), List.of(PROPS))));
    }

    @Test
    void geometryStep() throws Exception {
        GeometryStepRequest q = new GeometryStepRequest(2);
        q.setStep(9);
        q.set(0, 1, 2, 3, 4, 5, true);
        q.set(1, 6, 7, 8, 9, 10, false);
        GeometryStepRequest q2 = roundTrip(q);
        assertEquals(9, q2.step());
        assertEquals(2, q2.count());
        assertEquals(5, q2.moveMm(0));
        assertEquals(9, q2.turnDeg(1));
        assertTrue(q2.wantsSonar(0));
        assertFalse(q2.wantsSonar(1));
        assertEquals(OVERHEAD + 8 + 4 + 2 * (5 * 8 + 1) + 4, repeatedSize(q)); // (and no objects)

        GeometryStepResponse r = new GeometryStepResponse(2, 4);
        r.begin(9);
        r.setMotion(0, 250, 0, GeometryStepResponse.CONTACT_NONE, -1);
        r.setMotion(1, 12.5, 0, GeometryStepResponse.CONTACT_OBSTACLE, 3);
        r.addRange(1500);
        GeometryStepResponse r2 = roundTrip(r);
        assertEquals(9, r2.step());
        assertEquals(12.5, r2.movedMm(1));
        assertEquals(GeometryStepResponse.CONTACT_OBSTACLE, r2.contactKind(1));
        assertEquals(3, r2.contactIndex(1));
        assertEquals(1, r2.rangeCount());
        assertEquals(1500, r2.rangeMm(0));
        assertEquals(OVERHEAD + 8 + 4 + 2 * (8 + 8 + 1 + 4) + 4 + 8 + 4 + 4 + 4 + 4, repeatedSize(r)); // (no rays,
        // objects, grips or slides)
        r.addSlide(1, 3.5, -2);
        GeometryStepResponse slid = roundTrip(r);
        assertEquals(1, slid.slideCount());
        assertEquals(1, slid.slideRobot(0));
        assertEquals(3.5, slid.slideXMm(0));
        assertEquals(-2, slid.slideYMm(0));
        GeometryStepRequest sliding = new GeometryStepRequest(1);
        sliding.set(0, 1, 2, 3, 4, 5, GeometryStepRequest.SLIDE);
        assertTrue(roundTrip(sliding).slides(0));
        sliding.setAbsent(0);
        assertFalse(roundTrip(sliding).slides(0), "an absent robot does not slide");
    }

    @Test
    void viewerMessages() throws Exception {
        ViewerHello h = roundTrip(new ViewerHello(true));
        assertTrue(h.everyStep());
        assertEquals(30, roundTrip(new ViewerHello(false, 30)).maxUpdatesPerSecond());
        assertEquals("", roundTrip(new ViewerHello(false, 30)).watch());
        assertEquals("w3", roundTrip(new ViewerHello(false, 10, "w3")).watch());
        assertEquals(OVERHEAD + 4 + 1 + 4 + 2, repeatedSize(new ViewerHello(false)));

        PoseUpdate p = new PoseUpdate(4, new double[] {1, 2}, new double[] {3, 4}, new double[] {5, 6},
                new double[][] {{700, 800}, {}});
        PoseUpdate p2 = roundTrip(p);
        assertEquals(4, p2.step());
        assertEquals(2, p2.count());
        assertEquals(4, p2.yMm(1));
        assertEquals(6, p2.headingDeg(1));
        assertArrayEquals(new double[] {700, 800}, p2.sonarMm(0));
        assertEquals(0, p2.sonarMm(1).length);
        // tags, departed and held robots: three empty string lists; no objects, no LEDs, no loop functions
        assertEquals(OVERHEAD + 8 + 4 + 2 * (24 + 1) + 2 * 8 + 4 + 4 + 4 + 4 + 1 + 1, repeatedSize(p));
        PoseUpdate looped = roundTrip(p.withExperiment(List.of(new Floor.Region(new Floor.Disc(10, 20, 5), 0x000000)),
                List.of(new Light("l1", 0, 0, 100, 0xFFFF00, 1, true), new Light("l2", 0, 0, 100, 0xFFFF00, 1, true)),
                List.of(new Report("collected_food", 3)), robosim.protocol.Traces.NONE, robosim.protocol.Traces.NONE, new int[0]));
        assertEquals(List.of(new Floor.Region(new Floor.Disc(10, 20, 5), 0x000000)), looped.paint());
        assertEquals(List.of(new Report("collected_food", 3)), looped.reports());
        assertEquals(looped.paint(), looped.posesOnly().paint(), "a snapshot's poses keep the paint");
        assertEquals(2, looped.posesOnly().lightsOn().length);
        Light off = new Light("l2", 0, 0, 100, 0xFFFF00, 1, false);
        assertEquals(true, looped.light(List.of(off, off), 0).on(), "switched on by the loop functions");
        assertEquals(List.of(), p2.paint());
        assertEquals(off, p2.light(List.of(off), 0), "as the file's without loop functions");
        Traces.Log drawing = new Traces.Log();
        drawing.add("fb0", 1, 2, 0xFF0000);
        drawing.since();
        drawing.add("fb0", 3, 4, 0xFF0000);
        PoseUpdate drew = p.withExperiment(List.of(), List.of(), List.of(), drawing.since(), drawing.whole(), new int[0]);
        Traces sent = roundTrip(drew).traces();
        assertEquals(1, sent.firstPoint(), "a step's piece: its own point");
        assertEquals(1, sent.points());
        assertEquals(3, sent.xMm(1));
        PoseUpdate two = p.withScene(new double[] {1, 2}, new double[] {3, 4}, new double[] {0, 0}, null)
                .withExperiment(List.of(), List.of(), List.of(), Traces.NONE, Traces.NONE, new int[] {1});
        assertTrue(roundTrip(two).objectGone(1) && !roundTrip(two).objectGone(0), "object 1 out of the world");
        assertTrue(roundTrip(two.posesOnly()).objectGone(1), "a snapshot's poses too");
        Traces whole = roundTrip(drew.posesOnly()).traces();
        assertTrue(whole.fresh(), "a snapshot's poses hold the whole drawing");
        assertEquals(2, whole.points());
        assertEquals("fb0", whole.name(0));
        PoseUpdate tagged = new PoseUpdate(4, new double[] {1}, new double[] {3}, new double[] {5}, null,
                List.of("a>b"));
        assertEquals(List.of("a>b"), roundTrip(tagged).tags());
        PoseUpdate left = new PoseUpdate(4, new double[] {1}, new double[] {3}, new double[] {5}, null,
                List.of(), List.of("a"));
        assertEquals(List.of("a"), roundTrip(left).departed());
        PoseUpdate held = roundTrip(new PoseUpdate(4, new double[] {1, 2}, new double[] {3, 4}, new double[] {5, 6},
                null, List.of(), List.of("a"), List.of("b")));
        assertEquals(List.of("a"), held.departed());
        assertEquals(List.of("b"), held.held());

        Arena arena = new Arena(0, 0, 1000, 1000);
        PoseUpdate plain = new PoseUpdate(4, new double[] {1, 2}, new double[] {3, 4}, new double[] {5, 6});
        WorldSnapshot s = new WorldSnapshot(500, arena, List.of(), List.of("a", "b"), List.of(PROPS, PROPS), plain);
        WorldSnapshot s2 = roundTrip(s);
        assertEquals(4, s2.step());
        assertEquals(500, s2.timeStepMs());
        assertEquals(arena, s2.arena());
        assertEquals(List.of("a", "b"), s2.robotNames());
        assertEquals(250, s2.radiusMm(1));
        assertEquals(PROPS, s2.robots().get(0));
        assertEquals(3, s2.poses().yMm(0));
        int props = utf("ArRobot") + 5 * 8 + 4 + 5 * 8 + 4 + 4 + 1; // (no rays, no LEDs, no gripper)
        int robots = 2 * (utf("a") + props);
        int scenery = 4 + 4 + 1 + 4 + 4; // a plain floor (colour, no regions, no image), no lights, no objects
        assertEquals(wire(8 + 8 + 32 + 4 + 4 + robots + 8 + 4 + 2 * 25 + 4 + 4 + 4 + 4 + 1 + 1 + scenery),
                repeatedSize(s));

        RunState r = roundTrip(new RunState(12, RunState.Phase.PAUSED));
        assertEquals(12, r.step());
        assertEquals(RunState.Phase.PAUSED, r.phase());
        assertEquals(OVERHEAD + 8 + 1, repeatedSize(r));
        java.io.ByteArrayOutputStream bad = new java.io.ByteArrayOutputStream();
        try (java.io.ObjectOutputStream o = new java.io.ObjectOutputStream(bad)) {
            o.writeLong(1);
            o.writeByte(7);
        }
        java.io.ObjectInputStream in = new java.io.ObjectInputStream(new java.io.ByteArrayInputStream(bad.toByteArray()));
        ProtocolException refused = org.junit.jupiter.api.Assertions.assertThrows(ProtocolException.class,
                () -> new RunState().readExternal(in));
        assertEquals("run state phase must be 0..2, got 7", refused.getMessage());

        SimulationEnd e = roundTrip(new SimulationEnd(99, "done"));
        assertEquals(99, e.lastStep());
        assertEquals("done", e.reason());
        assertEquals(OVERHEAD + 8 + utf("done"), repeatedSize(e));
    }

    @Test
    void helloWithAnotherVersionIsReadUpToTheVersionAndTheStreamStaysInStep() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeUnshared(new RobotHello("robot1", PROPS));
            out.writeUnshared(new SimulationEnd(1, "after"));
        }
        byte[] data = bytes.toByteArray();
        byte[] versionThenName = {0, 0, 0, (byte) Protocol.VERSION, 0, 6, 'r', 'o', 'b', 'o', 't', '1'};
        int at = indexOf(data, versionThenName);
        assertTrue(at > 0, "version bytes found in the stream");
        data[at + 3] = (byte) (Protocol.VERSION + 1);
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(data))) {
            in.setObjectInputFilter(new ProtocolFilter());
            RobotHello h = (RobotHello) in.readUnshared();
            assertEquals(Protocol.VERSION + 1, h.protocolVersion());
            assertNull(h.name());
            assertEquals("after", ((SimulationEnd) in.readUnshared()).reason());
        }
    }

    private static int indexOf(byte[] data, byte[] pattern) {
        outer:
        for (int i = 0; i + pattern.length <= data.length; i++) {
            for (int j = 0; j < pattern.length; j++) {
                if (data[i + j] != pattern[j]) {
                    continue outer;
                }
            }
            return i;
        }
        return -1;
    }
}
