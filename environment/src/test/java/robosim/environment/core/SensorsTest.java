package robosim.environment.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.devices.RobotSensor;
import robosim.devices.Sensors;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.devices.DeviceSpec;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;
import robosim.protocol.RobotProperties;
import robosim.protocol.StepRequest;

/** The Environment's sensors, with numbers worked out by hand from the geometry. */
class SensorsTest {
    private static final Arena ARENA = new Arena(0, 0, 10_000, 10_000);
    /** A wall whose face is at x = 4 m, floor to ceiling. */
    private static final ObstacleShape WALL = ObstacleShape.rectangle("wall", 4000, 0, 100, 10_000);
    private static final List<DeviceSpec> ALL = List.of(new DeviceSpec("laser", "laser", Map.of()),
            new DeviceSpec("heat", "heat", Map.of()), new DeviceSpec("bump", "bump", Map.of()));

    private static InProcessSteps core(List<RobotSpec> robots, List<robosim.devices.HeatSource> heat, long seed) {
        WorldSpec spec = new WorldSpec("mem", "t", 500, seed, ARENA, List.of(WALL), robots, 0, 8192, heat);
        List<RobotProperties> props = new ArrayList<>();
        for (int i = 0; i < robots.size(); i++) {
            props.add(robosim.devices.RobotTypes.properties("ArRobot"));
        }
        return InProcessSteps.of(spec, props);
    }

    private static StepRequest ask(long k, double move, String... sensors) {
        return new StepRequest(k, move, 0, false, List.of(), List.of(sensors));
    }

    private static double[] reading(InProcessSteps core, int robot, String name) {
        return core.response(robot).readings().stream().filter(r -> r.name().equals(name)).findFirst()
                .orElseThrow().values();
    }

    @Test
    void laserBeamsReadTheDistanceToWallsAndRobots() throws Exception {
        // a at (1, 1) m facing +x: the wall's face is 3 m ahead; b stands 2 m straight up from a
        InProcessSteps core = core(List.of(new RobotSpec("a", "ArRobot", "", 1000, 1000, 0, ALL, 0),
                new RobotSpec("b", "ArRobot", "", 1000, 3000, 0)), List.of(), 1);
        core.step(0, new StepRequest[] {ask(0, 0, "laser"), null});
        double[] ranges = reading(core, 0, "laser");
        assertEquals(181, ranges.length, "180 degrees in 1 degree steps");
        assertEquals(3000, ranges[90], 1e-9, "the beam at 0 degrees, 3 m from the wall");
        assertEquals(3000 * Math.sqrt(2), ranges[135], 1e-6, "at +45 degrees");
        assertEquals(1000, ranges[0], 1e-9, "at -90 degrees: the arena's floor 1 m below");
        assertEquals(2000 - 250, ranges[180], 1e-9, "at +90 degrees: robot b's rim");
    }

    @Test
    void heatFallsOffWithDistanceAndAWallBlocksIt() throws Exception {
        // source of 10 at (2, 1) m; a 1 m from it reads 10 / (1 + 1); c behind the wall reads nothing
        InProcessSteps core = core(List.of(new RobotSpec("a", "ArRobot", "", 1000, 1000, 0, ALL, 0),
                new RobotSpec("c", "ArRobot", "", 5000, 1000, 0, ALL, 0)),
                List.of(new robosim.devices.HeatSource("fire", 2000, 1000, 10)), 1);
        core.step(0, new StepRequest[] {ask(0, 0, "heat"), ask(0, 0, "heat")});
        assertArrayEquals(new double[] {5}, reading(core, 0, "heat"), 1e-12);
        assertArrayEquals(new double[] {0}, reading(core, 1, "heat"), 0);
    }

    @Test
    void aHeatSourceOnAWallsFaceIsInSight() throws Exception {
        // the wall's face is at x = 4 m; a source on that face, 2 m from a: 10 / (1 + 4) = 2
        InProcessSteps core = core(List.of(new RobotSpec("a", "ArRobot", "", 2000, 1000, 0, ALL, 0)),
                List.of(new robosim.devices.HeatSource("lamp", 4000, 1000, 10)), 1);
        core.step(0, new StepRequest[] {ask(0, 0, "heat")});
        assertArrayEquals(new double[] {2}, reading(core, 0, "heat"), 1e-12);
    }

    @Test
    void aFailingSensorIsANoticeNotTheEndOfTheRun() throws Exception {
        List<DeviceSpec> failing = List.of(new DeviceSpec("broken", FailingTestSensor.class.getName(), Map.of()),
                new DeviceSpec("bump", "bump", Map.of()));
        InProcessSteps core = core(List.of(new RobotSpec("a", "ArRobot", "", 1000, 1000, 0, failing, 0)), List.of(), 1);
        core.step(0, new StepRequest[] {ask(0, 0, "broken", "bump")});
        assertEquals(List.of("sensor broken failed: java.lang.IllegalStateException: out of order"),
                core.response(0).notices());
        assertEquals(4, reading(core, 0, "bump").length, "the other sensors still answer");
    }

    @Test
    void bumpSaysWhichSideTouches() throws Exception {
        // a drives into the wall head on; d drives down onto b, touching b's left side with its front
        InProcessSteps core = core(List.of(new RobotSpec("a", "ArRobot", "", 3500, 5000, 0, ALL, 0),
                new RobotSpec("b", "ArRobot", "", 1000, 7000, 0, ALL, 0),
                new RobotSpec("d", "ArRobot", "", 1000, 7800, 270, ALL, 0)), List.of(), 1);
        core.step(0, new StepRequest[] {ask(0, 400, "bump"), ask(0, 0, "bump"), ask(0, 400, "bump")});
        assertEquals("wall", core.response(0).contact());
        assertArrayEquals(new double[] {1, 0, 0, 0}, reading(core, 0, "bump"), "a: front");
        assertArrayEquals(new double[] {0, 1, 0, 0}, reading(core, 1, "bump"), "b: left");
        assertArrayEquals(new double[] {1, 0, 0, 0}, reading(core, 2, "bump"), "d: front");
    }

    @Test
    void noiseComesFromTheWorldsSeedSoTheSameSeedGivesTheSameReadings() throws Exception {
        List<DeviceSpec> noisy = List.of(new DeviceSpec("laser", "laser", Map.of("fovDeg", "10", "noise", "20")));
        double[] first = noisyLaser(noisy, 7);
        assertArrayEquals(first, noisyLaser(noisy, 7), 0);
        assertNotEquals(first[0], noisyLaser(noisy, 8)[0]);
        // 11 beams from -5 to +5 degrees; without noise beam b reads 3000 / cos(b - 5 degrees)
        double spread = 0;
        for (int b = 0; b < first.length; b++) {
            spread = Math.max(spread, Math.abs(first[b] - 3000 / Math.cos(Math.toRadians(b - 5))));
        }
        assertEquals(11, first.length);
        assertTrue(spread > 0 && spread < 200, "noise of sigma 20 mm, largest deviation " + spread);
    }

    private static double[] noisyLaser(List<DeviceSpec> sensors, long seed) throws Exception {
        InProcessSteps core = core(List.of(new RobotSpec("a", "ArRobot", "", 1000, 1000, 0, sensors, 0)), List.of(),
                seed);
        core.step(0, new StepRequest[] {ask(0, 0, "laser")});
        core.step(1, new StepRequest[] {ask(1, 0, "laser")});
        return reading(core, 0, "laser");
    }

    @Test
    void aPlugInSensorIsOneClassNamedInTheWorld() throws Exception {
        List<DeviceSpec> compass = List.of(new DeviceSpec("compass", CompassTestSensor.class.getName(),
                Map.of("offsetDeg", "10")));
        InProcessSteps core = core(List.of(new RobotSpec("a", "ArRobot", "", 1000, 1000, 30, compass, 0)), List.of(), 1);
        core.step(0, new StepRequest[] {ask(0, 0, "compass", "nonsense")});
        assertArrayEquals(new double[] {40}, reading(core, 0, "compass"), 1e-12);
        assertEquals(List.of("no sensor named nonsense on a"), core.response(0).notices());
    }

    @Test
    void badSensorsAreRefusedWithTheReason() {
        assertEquals("type \"sniffer\" is neither " + Sensors.fileNames() + " nor a class on the class path",
                assertThrows(IllegalArgumentException.class, () -> Sensors.create("sniffer", Map.of())).getMessage());
        assertEquals("unknown attribute(s) [fov] for a laser sensor (it takes: " + String.join(", ", Sensors.info("laser")
                .attributes().stream().map(robosim.devices.Attribute::name).toList()) + ")",
                assertThrows(IllegalArgumentException.class, () -> Sensors.create("laser", Map.of("fov", "90")))
                        .getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> Sensors.create("laser", Map.of("resolutionDeg", "1e-8"))).getMessage()
                .endsWith("beams, more than 4096"));
        assertEquals("attribute rangeM value 'far' is not a number",
                assertThrows(IllegalArgumentException.class, () -> Sensors.create("laser", Map.of("rangeM", "far")))
                        .getMessage());
    }

    @Test
    void aClassThatIsNotASensorIsRefusedBeforeItIsInitialised() {
        assertEquals("class robosim.environment.core.NotASensor does not extend " + RobotSensor.class.getName(),
                assertThrows(IllegalArgumentException.class,
                        () -> Sensors.create("robosim.environment.core.NotASensor", Map.of())).getMessage());
        assertFalse(NotASensor.Initialised.notASensor, "its static initialiser ran");
    }
}
