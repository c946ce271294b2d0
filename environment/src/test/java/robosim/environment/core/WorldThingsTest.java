package robosim.environment.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.devices.RobotTypes;
import robosim.environment.config.EnvironmentLoader;
import robosim.protocol.Actuation;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;
import robosim.protocol.StepRequest;

/**
 * The floor, lights, objects, LEDs, cameras, range-and-bearing and the gripper through a whole step of the core, each
 * from an environment file, with numbers worked out by hand.
 */
class WorldThingsTest {
    @TempDir
    Path dir;

    private InProcessSteps world(String body) throws Exception {
        Path f = dir.resolve("world.xml");
        Files.writeString(f, "<environment name=\"things\" timeStepMs=\"100\" seed=\"1\"><arena width=\"6\" height=\"3\"/>"
                + body + "</environment>");
        WorldSpec spec = new EnvironmentLoader().load(f);
        List<RobotProperties> props = new ArrayList<>();
        for (WorldSpec.RobotSpec r : spec.robots()) {
            props.add(RobotTypes.properties(r.type()));
        }
        return InProcessSteps.of(spec, props);
    }

    private static StepRequest ask(long k, double move, double turn, String... sensors) {
        return new StepRequest(k, move, turn, false, List.of(), List.of(sensors));
    }

    private static double[] reading(InProcessSteps core, int robot, String name) {
        return core.response(robot).readings().stream().filter(r -> r.name().equals(name)).findFirst()
                .orElseThrow().values();
    }

    @Test
    void theGroundSensorsReadThePaintUnderThem() throws Exception {
        // white floor, black square from (1, 1) to (1.5, 1.5) m. A foot-bot's ground points are (63, 11.6) mm
        // front-left, (-63, 11.6) back-left, (-63, -11.6) back-right, (63, -11.6) front-right of its centre.
        // a at (1, 1) m facing +x: only front-left, at (1.063, 1.0116), is on the square.
        // b at (2, 1) m over a second square from (2, 1) to (2.5, 1.5), facing +y:
        // front-right (63, -11.6) turns to (11.6, 63), at (2.0116, 1.063): on it; front-left turns to (-11.6, 63): off.
        InProcessSteps core = world("<floor colour=\"white\"><rectangle x=\"1\" y=\"1\" width=\"0.5\" height=\"0.5\" "
                + "colour=\"black\"/><rectangle x=\"2\" y=\"1\" width=\"0.5\" height=\"0.5\" colour=\"black\"/></floor>"
                + "<robots><robot name=\"a\" type=\"foot-bot\" x=\"1\" y=\"1\" heading=\"0\">"
                + "<sensor name=\"paint\" type=\"ground\" read=\"colour\"/></robot>"
                + "<robot name=\"b\" type=\"foot-bot\" x=\"2\" y=\"1\" heading=\"90\"/></robots>");
        core.step(0, new StepRequest[] {ask(0, 0, 0, "ground", "paint"), ask(0, 0, 0, "ground")});
        assertArrayEquals(new double[] {0, 1, 1, 1}, reading(core, 0, "ground"), 1e-12);
        assertArrayEquals(new double[] {1, 1, 1, 0}, reading(core, 1, "ground"), 1e-12);
        assertArrayEquals(new double[] {0x000000, 0xFFFFFF, 0xFFFFFF, 0xFFFFFF}, reading(core, 0, "paint"), 0,
                "the colours on request");
    }

    @Test
    void aLightAheadShinesOnTheFrontSensorsAndAWallHidesIt() throws Exception {
        // a lamp of intensity 1 on the floor at (2, 1) m; a 1 m from it, facing it: r = 1, exp(-2 r) = e^-2. The
        // sensors at +-7.5 degrees read e^-2 (1 - 7.5 / 90); one at 97.5 degrees, more than 90 away, reads 0.
        // c at (4, 1) m is 2 m away but behind a wall from x = 3 to 3.1 m: nothing.
        InProcessSteps core = world("<obstacles><rectangle name=\"wall\" x=\"3\" y=\"0\" width=\"0.1\" height=\"3\"/>"
                + "</obstacles><lights><light name=\"lamp\" x=\"2\" y=\"1\" height=\"0\" intensity=\"1\"/></lights>"
                + "<robots><robot name=\"a\" type=\"foot-bot\" x=\"1\" y=\"1\" heading=\"0\"/>"
                + "<robot name=\"c\" type=\"foot-bot\" x=\"4\" y=\"1\" heading=\"180\"/></robots>");
        core.step(0, new StepRequest[] {ask(0, 0, 0, "light"), ask(0, 0, 0, "light")});
        double[] a = reading(core, 0, "light");
        assertEquals(24, a.length);
        double front = Math.exp(-2) * (1 - 7.5 / 90);
        assertEquals(front, a[0], 1e-12, "7.5 degrees");
        assertEquals(front, a[23], 1e-12, "352.5 degrees");
        assertEquals(Math.exp(-2) * (1 - 22.5 / 90), a[1], 1e-12, "22.5 degrees");
        assertEquals(0, a[6], 0, "97.5 degrees");
        assertArrayEquals(new double[24], reading(core, 1, "light"), 0);
    }

    @Test
    void aRangeAndBearingMessageArrivesTheSameStepWithItsBearing() throws Exception {
        // b stands 1 m straight to a's left (a faces +x): a hears b at 1000 mm, bearing +90 degrees; b, facing +y,
        // has a straight behind it: bearing 180. Both foot-bots' devices sit at the same height.
        InProcessSteps core = world("<robots><robot name=\"a\" type=\"foot-bot\" x=\"1\" y=\"1\" heading=\"0\"/>"
                + "<robot name=\"b\" type=\"foot-bot\" x=\"1\" y=\"2\" heading=\"90\"/></robots>");
        double[] bytesOfB = {7, 0, 0, 0, 0, 0, 0, 0, 0, 255};
        double[] bytesOfA = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
        core.step(0, new StepRequest[] {
            ask(0, 0, 0, "rab").with(List.of(new Actuation("rab", bytesOfA)), StepRequest.Gripper.STAY),
            ask(0, 0, 0, "rab").with(List.of(new Actuation("rab", bytesOfB)), StepRequest.Gripper.STAY)});
        double[] heardByA = reading(core, 0, "rab");
        assertEquals(12, heardByA.length, "one message: range, bearing, 10 bytes");
        assertEquals(1000, heardByA[0], 1e-9);
        assertEquals(90, heardByA[1], 1e-9);
        assertArrayEquals(bytesOfB, java.util.Arrays.copyOfRange(heardByA, 2, 12), 0);
        double[] heardByB = reading(core, 1, "rab");
        assertEquals(180, Math.abs(heardByB[1]), 1e-9);
        assertArrayEquals(bytesOfA, java.util.Arrays.copyOfRange(heardByB, 2, 12), 0);
        // the next step, nothing new set: the devices send what they were given again
        core.step(1, new StepRequest[] {ask(1, 0, 0, "rab"), ask(1, 0, 0, "rab")});
        assertEquals(12, reading(core, 0, "rab").length);
    }

    @Test
    void aCameraSeesALitBeaconAndViewersSeeTheColours() throws Exception {
        // b 0.5 m to a's left lights its beacon (LED 12, on its centre line) red: a's camera sees one red blob at
        // 500 mm, 90 degrees; LEDs left black are off and unseen
        InProcessSteps core = world("<robots><robot name=\"a\" type=\"foot-bot\" x=\"1\" y=\"1\" heading=\"0\"/>"
                + "<robot name=\"b\" type=\"foot-bot\" x=\"1\" y=\"1.5\" heading=\"0\"/></robots>");
        double[] colours = new double[13];
        colours[12] = 0xFF0000;
        core.step(0, new StepRequest[] {ask(0, 0, 0, "camera"),
            ask(0, 0, 0).with(List.of(new Actuation("leds", colours)), StepRequest.Gripper.STAY)});
        assertArrayEquals(new double[] {0xFF0000, 500, 90}, reading(core, 0, "camera"), 1e-9);
        PoseUpdate seen = core.viewerUpdate();
        assertEquals(0xFF0000, seen.leds(1)[12]);
        assertEquals(13, seen.leds(0).length, "a's 13 LEDs, all off");
        assertEquals(0, java.util.Arrays.stream(seen.leds(0)).max().orElseThrow());
    }

    @Test
    void aPushedBoxStopsAtTheWallAndSoDoesTheRobot() throws Exception {
        // a box 0.2 m wide, centre (2, 1) m, a wall's face at x = 2.5 m. The foot-bot (radius r = 85.04 mm) at x = 1.8 m
        // is about 15 mm short of the box's face at 1.9 m. Driving 1 m: the box can go 0.4 m (its face to the wall's
        // 2.5 m), so it ends with its centre at 2.4 m and the robot at 2.3 m - r, each against what is ahead.
        InProcessSteps core = world("<obstacles><rectangle name=\"wall\" x=\"2.5\" y=\"0\" width=\"0.1\" height=\"3\"/>"
                + "</obstacles><objects><box name=\"crate\" x=\"2\" y=\"1\" width=\"0.2\" depth=\"0.2\" movable=\"true\" "
                + "mass=\"0.5\" friction=\"0.1\"/></objects>"
                + "<robots><robot name=\"a\" type=\"foot-bot\" x=\"1.8\" y=\"1\" heading=\"0\"/></robots>");
        for (int k = 0; k < 50; k++) {
            core.step(k, new StepRequest[] {ask(k, 20, 0)});
        }
        PoseUpdate seen = core.viewerUpdate();
        assertEquals(2400, seen.objectXMm(0), 1e-6, "the box against the wall");
        assertEquals(1000, seen.objectYMm(0), 1e-9);
        double r = RobotTypes.properties("foot-bot").radiusMm();
        assertEquals(2300 - r, seen.xMm(0), 1e-5, "the robot against the box (two contact gaps of 1e-6 mm)");
        assertEquals("crate", core.response(0).contact());
    }

    @Test
    void aGrippedCylinderIsCarriedRoundACorner() throws Exception {
        // a cylinder of radius 50 mm at (1.14, 1) m touches the gripper of a foot-bot at (1, 1) m facing +x (its rim
        // at 1.085 m, the gripper's reach 10 mm). Gripped, it keeps its place in the robot's frame, 140 mm ahead:
        // after 500 mm along +x and a quarter turn left and 500 mm along +y, it is at (1.5, 1.5 + 0.14) m.
        InProcessSteps core = world("<objects><cylinder name=\"can\" x=\"1.14\" y=\"1\" radius=\"0.05\" height=\"0.1\" "
                + "movable=\"true\" gripable=\"true\" mass=\"0.1\"/></objects>"
                + "<robots><robot name=\"a\" type=\"foot-bot\" x=\"1\" y=\"1\" heading=\"0\"/></robots>");
        core.step(0, new StepRequest[] {ask(0, 0, 0).with(List.of(), StepRequest.Gripper.GRIP)});
        assertEquals("can", core.response(0).gripped());
        long k = 1;
        for (int i = 0; i < 25; i++, k++) {
            core.step(k, new StepRequest[] {ask(k, 20, 0)});
        }
        for (int i = 0; i < 9; i++, k++) {
            core.step(k, new StepRequest[] {ask(k, 0, 10)});
        }
        for (int i = 0; i < 25; i++, k++) {
            core.step(k, new StepRequest[] {ask(k, 20, 0)});
        }
        PoseUpdate seen = core.viewerUpdate();
        assertEquals(1500, seen.xMm(0), 1e-6);
        assertEquals(1500, seen.yMm(0), 1e-6);
        assertEquals(1500, seen.objectXMm(0), 1e-6);
        assertEquals(1640, seen.objectYMm(0), 1e-6);
        assertEquals("can", core.response(0).gripped());
        core.step(k, new StepRequest[] {ask(k, 0, 0).with(List.of(), StepRequest.Gripper.RELEASE)});
        assertEquals("", core.response(0).gripped());
        k++;
        core.step(k, new StepRequest[] {ask(k, -100, 0)});
        assertEquals(1640, core.viewerUpdate().objectYMm(0), 1e-6, "released, it stays where it was left");
        assertTrue(core.viewerUpdate().yMm(0) < 1500);
    }
}
