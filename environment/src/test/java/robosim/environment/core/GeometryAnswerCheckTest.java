package robosim.environment.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.ProtocolException;
import robosim.protocol.StepRequest;

/** The core takes nothing from Geometry on trust: a bad answer is refused and changes nothing. */
class GeometryAnswerCheckTest {
    private static final WorldSpec TWO = new WorldSpec("mem", "two", 500, 1, new Arena(0, 0, 10_000, 10_000),
            List.of(), List.of(new WorldSpec.RobotSpec("a", "ArRobot", "", 1000, 1000, 0),
                    new WorldSpec.RobotSpec("b", "ArRobot", "", 1000, 5000, 0)), 0, 8192, List.of());

    private static SimulationCore core() {
        return new SimulationCore(TWO, List.of(robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("ArRobot")));
    }

    private static StepRequest[] moveBoth(long k) {
        return new StepRequest[] {new StepRequest(k, 200, 0, true, List.of()), new StepRequest(k, 200, 0, false, List.of())};
    }

    /** A correct answer to {@code asked}, from the real geometry, changed by {@code tamper}. */
    private static GeometryStepResponse answer(SimulationCore core, GeometryStepRequest asked,
            Consumer<GeometryStepResponse> tamper) {
        GeometryStepResponse good = new InProcessGeometry(core.map().geometryWorld()).resolve(asked);
        GeometryStepResponse copy = new GeometryStepResponse(2, 16);
        copy.begin(good.step());
        for (int i = 0; i < 2; i++) {
            copy.setMotion(i, good.movedMm(i), good.turnedDeg(i), good.contactKind(i), good.contactIndex(i));
        }
        for (int r = 0; r < good.rangeCount(); r++) {
            copy.addRange(good.rangeMm(r));
        }
        tamper.accept(copy);
        return copy;
    }

    private static void refused(Consumer<GeometryStepResponse> tamper, String what) throws Exception {
        SimulationCore core = core();
        GeometryStepRequest[] asked = new GeometryStepRequest[1];
        assertFalse(core.step(0, moveBoth(0), request -> {
            asked[0] = request;
            return null; // (answered later, as a Geometry process does)
        }));
        ProtocolException e = assertThrows(ProtocolException.class, () -> core.answer(answer(core, asked[0], tamper)));
        assertTrue(e.getMessage().contains(what), e.getMessage());
        core.answer(answer(core, asked[0], g -> { })); // the step is still there to complete with a good answer
        assertEquals(1200, core.response(0).xMm(), 1e-9);
    }

    @Test
    void aContactWithARobotThatDoesNotExistIsRefused() throws Exception {
        refused(g -> g.setMotion(0, 0, 0, GeometryStepResponse.CONTACT_ROBOT, 99_999), "index 99999");
    }

    @Test
    void aMotionLongerThanAskedOrNotFiniteIsRefused() throws Exception {
        refused(g -> g.setMotion(1, 5000, 0, GeometryStepResponse.CONTACT_NONE, -1), "asked 200.0 mm");
        refused(g -> g.setMotion(1, Double.NaN, 0, GeometryStepResponse.CONTACT_NONE, -1), "NaN");
    }

    @Test
    void theWrongStepOrTooFewSonarRangesOrANegativeRangeAreRefused() throws Exception {
        refused(g -> g.begin(7), "step 7");
        refused(g -> g.begin(0), "0 sonar ranges and 0 rays, expected "
                + robosim.devices.RobotTypes.properties("ArRobot").sonars().size() + " and 0");
        refused(g -> {
            g.begin(0);
            for (int s = 0; s < robosim.devices.RobotTypes.properties("ArRobot").sonars().size(); s++) {
                g.addRange(-1);
            }
        }, "sonar range -1.0 mm");
    }

    /** {@code good}'s motions and object poses (two robots, three objects), to tamper with. */
    private static GeometryStepResponse copyOf(GeometryStepResponse good) {
        GeometryStepResponse bad = new GeometryStepResponse(2, 16, 64, 3);
        bad.begin(good.step());
        for (int i = 0; i < 2; i++) {
            bad.setMotion(i, good.movedMm(i), good.turnedDeg(i), good.contactKind(i), good.contactIndex(i));
        }
        for (int o = 0; o < 3; o++) {
            bad.setObject(o, good.objectXMm(o), good.objectYMm(o), good.objectHeadingDeg(o));
        }
        return bad;
    }

    @Test
    void aFixedObjectMovedOrAGripOfWhatCannotBeTakenIsRefused(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        // a fixed crate (0), a gripable can (1) 5 mm ahead of a's gripper, a movable rock (2) 5 mm ahead of b's
        java.nio.file.Path file = dir.resolve("w.xml");
        java.nio.file.Files.writeString(file, "<environment timeStepMs=\"100\"><arena width=\"4\" height=\"4\"/>"
                + "<objects><box name=\"crate\" x=\"3\" y=\"3\" width=\"0.2\" depth=\"0.2\"/><cylinder name=\"can\" "
                + "x=\"1.14\" y=\"1\" radius=\"0.05\" movable=\"true\" gripable=\"true\"/><cylinder name=\"rock\" "
                + "x=\"1.14\" y=\"2\" radius=\"0.05\" movable=\"true\"/></objects><robots><robot name=\"a\" "
                + "type=\"foot-bot\" x=\"1\" y=\"1\"/><robot name=\"b\" type=\"foot-bot\" x=\"1\" y=\"2\"/></robots>"
                + "</environment>");
        WorldSpec spec = new robosim.environment.config.EnvironmentLoader().load(file);
        for (Consumer<GeometryStepResponse> tamper : List.<Consumer<GeometryStepResponse>>of(
                g -> g.setObject(0, 3001, 3000, 0),
                g -> g.addGrip(1, 2),
                g -> {
                    g.addGrip(0, 1);
                    g.addGrip(1, 1);
                })) {
            SimulationCore core = new SimulationCore(spec, List.of(robosim.devices.RobotTypes.properties("foot-bot"),
                    robosim.devices.RobotTypes.properties("foot-bot")));
            GeometryStepRequest[] asked = new GeometryStepRequest[1];
            StepRequest grip = new StepRequest(0, 0, 0, false, List.of()).with(List.of(), StepRequest.Gripper.GRIP);
            assertFalse(core.step(0, new StepRequest[] {grip, grip}, request -> {
                asked[0] = request;
                return null;
            }));
            GeometryStepResponse good = new InProcessGeometry(core.map().geometryWorld()).resolve(asked[0]);
            GeometryStepResponse bad = copyOf(good);
            tamper.accept(bad);
            ProtocolException e = assertThrows(ProtocolException.class, () -> core.answer(bad));
            assertTrue(e.getMessage().contains("fixed") || e.getMessage().contains("cannot have"), e.getMessage());
            core.answer(good);
            assertEquals("can", core.response(0).gripped(), "the good answer: a takes the can");
            assertEquals("", core.response(1).gripped(), "the rock is not gripable");
        }
        // the rock out of the world (its loop functions took it out): moved, or touched, is refused
        for (Consumer<GeometryStepResponse> tamper : List.<Consumer<GeometryStepResponse>>of(
                g -> g.setObject(2, 1141, 2000, 0),
                g -> g.setMotion(1, 0, 0, GeometryStepResponse.CONTACT_OBJECT, 2))) {
            SimulationCore core = new SimulationCore(spec, List.of(robosim.devices.RobotTypes.properties("foot-bot"),
                    robosim.devices.RobotTypes.properties("foot-bot")));
            core.map().objectGone(2, true);
            GeometryStepRequest[] asked = new GeometryStepRequest[1];
            StepRequest still = new StepRequest(0, 0, 0, false, List.of());
            assertFalse(core.step(0, new StepRequest[] {still, still}, request -> {
                asked[0] = request;
                return null;
            }));
            assertEquals(GeometryStepRequest.GONE, asked[0].carrier(2));
            GeometryStepResponse good = new InProcessGeometry(core.map().geometryWorld()).resolve(asked[0]);
            GeometryStepResponse bad = copyOf(good);
            tamper.accept(bad);
            ProtocolException e = assertThrows(ProtocolException.class, () -> core.answer(bad));
            assertTrue(e.getMessage().contains("out of the world") || e.getMessage().contains("does not exist"),
                    e.getMessage());
        }
    }
}
