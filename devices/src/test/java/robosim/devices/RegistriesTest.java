package robosim.devices;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The registries: each member found by its class alone, configured and checked from its own declaration. */
class RegistriesTest {
    /** A world of one robot at the origin heading 0, whose rays meet a wall {@code wallMm} away, and noise of 5 sigma. */
    private static final class Probe implements SensorContext {
        private final double wallMm;

        Probe(double wallMm) {
            this.wallMm = wallMm;
        }

        @Override
        public int robot() {
            return 0;
        }

        @Override
        public double xMm() {
            return 0;
        }

        @Override
        public double yMm() {
            return 0;
        }

        @Override
        public double headingDeg() {
            return 0;
        }

        @Override
        public double radiusMm() {
            return 100;
        }

        @Override
        public double ray(double worldAngleDeg, double maxMm) {
            return Math.min(wallMm, maxMm);
        }

        @Override
        public boolean clearTo(double xMm, double yMm) {
            return true;
        }

        @Override
        public List<HeatSource> heatSources() {
            return List.of(new HeatSource("h", 1000, 0, 10));
        }

        @Override
        public int touching(double toleranceMm, double[] out) {
            return 0;
        }

        @Override
        public double sonarRange(int sonar) {
            return wallMm;
        }

        @Override
        public double rayRange(int ray) {
            return wallMm;
        }

        @Override
        public int floorColour(double xMm, double yMm) {
            return 0xFFFFFF;
        }

        @Override
        public List<robosim.protocol.Light> lights() {
            return List.of();
        }

        @Override
        public boolean sight(double fromZMm, double xMm, double yMm, double zMm, int other) {
            return true;
        }

        @Override
        public void leds(double rangeMm, LedVisitor visitor) {
        }

        @Override
        public List<RabMessage> rabReceived() {
            return List.of();
        }

        @Override
        public double gaussian() {
            return 5; // (five standard deviations, every draw: a value's noise must still leave it in its range)
        }
    }

    @Test
    void everyBuiltInSensorIsFoundByItsClassAloneAndSaysWhatItIs() {
        for (SensorInfo s : Sensors.all()) {
            assertTrue(s.summary().length() > 10 && s.values().length() > 10, s.name());
            assertNotNull(s.display(), s.name());
        }
        assertTrue(Sensors.all().stream().anyMatch(SensorInfo::geometry), "sonar, the Geometry process's");
        assertEquals(Sensors.all().stream().filter(s -> !s.geometry()).map(SensorInfo::name).toList(),
                List.of(Sensors.fileNames().split(", ")));
        assertNull(Sensors.info("sniffer"));
    }

    @Test
    void aReadingIsShownAsTheSensorItsNameSaysItIsOf() {
        assertEquals("laser", Sensors.kindOf("laser", 181).name());
        assertEquals("laser", Sensors.kindOf("front-laser", 90).name(), "a name that holds a sensor's");
        assertEquals(SensorInfo.Display.SIDES, Sensors.display("Rear_Bump", 4));
        assertNull(Sensors.kindOf("rear_bump", 3), "sides only with as many values as there are sides");
        assertNull(Sensors.kindOf("bump", 1), "nor by its exact name (a heat sensor named bump)");
        assertNull(Sensors.kindOf("heatmap", 100), "a word, not a part of one");
        assertNull(Sensors.kindOf("com.example.HeatCamera", 1), "a class name's words are not parted by case");
        assertNull(Sensors.kindOf("sonar_laser", 181), "two kinds named: neither");
        assertEquals(SensorInfo.Display.RANGES, Sensors.display("heatmap", 100), "an unknown one's many values");
        assertEquals(SensorInfo.Display.RANGES, Sensors.display("gas", Sensors.RANGES_FROM), "one's own, many values");
        assertEquals(SensorInfo.Display.VALUES, Sensors.display("gas", 2));
    }

    @Test
    void aSensorReadsItsDeclaredAttributesAndRefusesOthersSayingWhichItTakes() {
        RobotSensor laser = Sensors.create("laser", Map.of("fovDeg", "90", "resolutionDeg", "0.5", "rangeM", "4"));
        assertEquals(new SensorValues(181, 0, 4000, "mm"), laser.values());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Sensors.create("laser", Map.of("fov", "90")));
        assertEquals("unknown attribute(s) [fov] for a laser sensor (it takes: fovDeg, resolutionDeg, rangeM, noise)",
                e.getMessage());
        assertEquals("fovDeg must be in (0, 360], got 400.0", assertThrows(IllegalArgumentException.class,
                () -> Sensors.create("laser", Map.of("fovDeg", "400"))).getMessage());
        assertEquals("noise must be >= 0, got -1.0", assertThrows(IllegalArgumentException.class,
                () -> Sensors.create("heat", Map.of("noise", "-1"))).getMessage());
    }

    @Test
    void aSensorsNoiseIsItsOwnAndKeepsEachValueInItsRange() {
        double[] near = Sensors.create("laser", Map.of("noise", "100", "rangeM", "2")).generateSensorResponse(
                new Probe(1900));
        assertEquals(2000, near[90], 0, "1900 + 5 x 100 held to the 2 m range");
        double[] bump = Sensors.create("bump", Map.of("noise", "1")).generateSensorResponse(new Probe(5000));
        assertEquals(List.of(1.0, 1.0, 1.0, 1.0), java.util.Arrays.stream(bump).boxed().toList(), "0 + 5 held to 1");
        double[] clean = Sensors.create("heat", Map.of()).generateSensorResponse(new Probe(5000));
        assertEquals(10 / (1 + 1.0), clean[0], 1e-12, "no noise: no number drawn");
    }

    @Test
    void aRobotTypeIsItsBodyAndItsDevicesAndTheHandshakeIsMadeFromThem() {
        assertTrue(RobotTypes.names().containsAll(List.of("ArRobot", "Scout")), RobotTypes.names().toString());
        RobotType scout = RobotTypes.byName("Scout");
        assertEquals(16, scout.properties().sonars().size());
        assertEquals(scout.body().radiusMm(), scout.properties().radiusMm());
        assertEquals(500, scout.defaultVelocityMmPerS());
        assertEquals("robot type \"Roomba\" is neither " + String.join(", ", RobotTypes.names()) + " nor a RobotType "
                + "class on the class path",
                assertThrows(IllegalArgumentException.class, () -> RobotTypes.byName("Roomba")).getMessage());
    }

    @Test
    void aVelocityBecomesAStepsMotionInOnePlace() {
        assertEquals(250, Drive.perStep(500, Drive.seconds(500)));
        assertEquals(-100, Drive.piece(-100, 500, 0.5), "the rest of a move, backwards");
        assertEquals(250, Drive.piece(750, 500, 0.5), "a step's worth of a longer move");
    }
}
