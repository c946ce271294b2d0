package robosim.environment.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.environment.core.WorldSpec;
import robosim.protocol.WorldObject;

/** An environment file's floor, lights and objects and its {@code <distribute>}s: what they place, their faults. */
class SceneryAndDistributeTest {
    @TempDir
    Path dir;

    private static final String ROBOT = "<robots><robot name=\"r\" type=\"foot-bot\" x=\"0.5\" y=\"0.5\"/></robots>";

    private Path write(String body) throws IOException {
        Path f = dir.resolve("env.xml");
        Files.writeString(f, "<environment timeStepMs=\"100\" seed=\"7\"><arena width=\"4\" height=\"4\"/>" + body
                + "</environment>");
        return f;
    }

    private WorldSpec load(String body) throws Exception {
        return new EnvironmentLoader().load(write(body));
    }

    /** The one-line fault of a file holding {@code body}, starting with the file's name. */
    private String fault(String body) throws IOException {
        Path f = write(body);
        String m = assertThrows(EnvironmentFileException.class, () -> new EnvironmentLoader().load(f)).getMessage();
        assertTrue(m.startsWith(f.toString()), m);
        assertEquals(1, m.lines().count(), m);
        return m;
    }

    @Test
    void floorLightsAndObjectsAreReadInMillimetres() throws Exception {
        WorldSpec w = load("<floor colour=\"gray50\"><circle x=\"2\" y=\"2\" radius=\"0.5\" colour=\"black\"/></floor>"
                + "<lights><light name=\"l\" x=\"1\" y=\"3\" height=\"0.5\" intensity=\"2\" colour=\"yellow\"/></lights>"
                + "<objects><cylinder name=\"can\" x=\"3\" y=\"3\" radius=\"0.05\" movable=\"true\" gripable=\"true\"/>"
                + "<box name=\"crate\" x=\"3\" y=\"1\" width=\"0.4\" depth=\"0.2\" heading=\"90\"/></objects>" + ROBOT);
        assertEquals(0x000000, w.scenery().floor().colourAt(w.arena(), 2000, 2000));
        assertEquals(0x7F7F7F, w.scenery().floor().colourAt(w.arena(), 100, 100));
        assertEquals(500, w.scenery().lights().get(0).heightMm(), 1e-9);
        List<WorldObject> o = w.scenery().objects();
        assertEquals(List.of("can", "crate"), o.stream().map(WorldObject::name).toList());
        assertEquals(100, o.get(0).widthMm(), 1e-9);
        assertTrue(o.get(0).gripable() && o.get(0).movable());
        assertEquals(90, o.get(1).headingDeg(), 1e-9);
        assertTrue(!o.get(1).movable());
    }

    @Test
    void eachBadThingIsOneLineNamingItAndTheValue() throws Exception {
        assertTrue(fault("<floor colour=\"mauveish\"/>" + ROBOT).contains("<floor> colour 'mauveish' is not a colour"));
        assertTrue(fault("<lights><light name=\"l\" x=\"1\" y=\"1\" height=\"-0.1\"/></lights>" + ROBOT)
                .contains("<light name=\"l\"> height must be >= 0 m (a light cannot be below the floor), got -0.1"));
        assertTrue(fault("<objects><box name=\"a\" x=\"2\" y=\"2\" width=\"1\" depth=\"1\"/><cylinder name=\"b\" "
                + "x=\"2.4\" y=\"2.4\" radius=\"0.2\"/></objects>" + ROBOT)
                .contains("<cylinder name=\"b\"> at (2.4, 2.4) m overlaps object \"a\""));
        assertTrue(fault("<objects><box name=\"a\" x=\"0.55\" y=\"0.55\" width=\"0.1\" depth=\"0.1\"/></objects>" + ROBOT)
                .contains("<robot name=\"r\"> at (0.5, 0.5) m overlaps object \"a\""));
        assertTrue(fault("<objects><cylinder name=\"c\" x=\"1\" y=\"1\" radius=\"0.1\" gripable=\"true\"/></objects>"
                + ROBOT).contains("<cylinder name=\"c\"> is gripable, so it must be movable=\"true\" too"));
        assertTrue(fault("<robots><robot name=\"r\" type=\"foot-bot\" x=\"1\" y=\"1\" devices=\"leds sonar-x\"/>"
                + "</robots>").contains("devices: a foot-bot has no device \"sonar-x\""));
        Files.writeString(dir.resolve("floor.png"), "GIF89a, not a PNG");
        assertTrue(fault("<floor image=\"floor.png\"/>" + ROBOT).contains("<floor> image \"floor.png\": not a PNG image"));
        assertTrue(fault("<floor image=\"nowhere.png\"/>" + ROBOT).contains("no such file"));
    }

    @Test
    void aGridPlacesRowByRowFromTheLowerLeft() throws Exception {
        // 3 columns 0.5 m apart and 2 rows 1 m apart round (2, 2): x 1.5, 2, 2.5; y 1.5, 2.5
        WorldSpec w = load("<distribute><position method=\"grid\" center=\"2,2,0\" distances=\"0.5,1,0\" "
                + "layout=\"3,2,1\"/><orientation method=\"constant\" values=\"90,0,0\"/><entity quantity=\"5\" "
                + "baseNum=\"1\"><robot name=\"fb\" type=\"foot-bot\"/></entity></distribute>");
        List<WorldSpec.RobotSpec> r = w.robots();
        assertEquals(List.of("fb1", "fb2", "fb3", "fb4", "fb5"), r.stream().map(WorldSpec.RobotSpec::name).toList());
        double[][] at = {{1500, 1500}, {2000, 1500}, {2500, 1500}, {1500, 2500}, {2000, 2500}};
        for (int i = 0; i < at.length; i++) {
            assertEquals(at[i][0], r.get(i).xMm(), 1e-9);
            assertEquals(at[i][1], r.get(i).yMm(), 1e-9);
            assertEquals(90, r.get(i).headingDeg(), 1e-9);
        }
        assertEquals(List.of("rab", "leds"), r.get(0).actuators().stream().map(a -> a.name()).toList());
    }

    @Test
    void uniformDrawsStayInsideTheirBoundsApartAndFollowTheSeed() throws Exception {
        String body = "<distribute><position method=\"uniform\" min=\"1,1\" max=\"3,3\"/><orientation "
                + "method=\"uniform\" min=\"0\" max=\"360\"/><entity quantity=\"20\" maxTrials=\"1000\"><cylinder "
                + "name=\"can\" radius=\"0.05\" movable=\"true\"/></entity></distribute>" + ROBOT;
        WorldSpec a = load(body);
        List<WorldObject> cans = a.scenery().objects();
        assertEquals(20, cans.size());
        for (int i = 0; i < cans.size(); i++) {
            WorldObject c = cans.get(i);
            assertEquals("can" + i, c.name());
            assertTrue(c.xMm() >= 1000 && c.xMm() < 3000 && c.yMm() >= 1000 && c.yMm() < 3000, c.toString());
            for (int j = 0; j < i; j++) {
                assertTrue(Math.hypot(c.xMm() - cans.get(j).xMm(), c.yMm() - cans.get(j).yMm()) >= 100, "apart");
            }
        }
        assertEquals(cans, load(body).scenery().objects(), "the same seed, the same world");
        Path other = dir.resolve("other.xml");
        Files.writeString(other, Files.readString(dir.resolve("env.xml")).replace("seed=\"7\"", "seed=\"8\""));
        assertNotEquals(cans, new EnvironmentLoader().load(other).scenery().objects(), "another seed, another world");
        assertEquals(new EnvironmentLoader().load(other).scenery().objects(), a.withSeed(8).scenery().objects(),
                "a seed given later (--seed, a sweep's, an episode's) draws as the file's own would");
        assertEquals(8, a.withSeed(8).seed());
        assertEquals(cans, a.withSeed(8).withSeed(7).scenery().objects());
    }

    @Test
    void aSeedWhoseDrawsPlaceAnEntityNowhereIsOneLine() throws Exception {
        // two kilobots (33 mm across) drawn once each from a 60 mm square: some seeds place both, some cannot
        String body = "<distribute><position method=\"uniform\" min=\"1,1\" max=\"1.06,1.06\"/><entity "
                + "quantity=\"2\" maxTrials=\"1\"><robot name=\"k\" type=\"kilobot\"/></entity></distribute>";
        WorldSpec w = null;
        for (int seed = 1; w == null && seed < 500; seed++) {
            Path f = write(body);
            Files.writeString(f, Files.readString(f).replace("seed=\"7\"", "seed=\"" + seed + "\""));
            try {
                w = new EnvironmentLoader().load(f);
            } catch (EnvironmentFileException e) {
                assertTrue(e.getMessage().contains("could not place k1"), e.getMessage());
            }
        }
        assertTrue(w != null, "a seed that places both");
        String refused = null;
        for (long seed = 0; seed < 500 && refused == null; seed++) {
            try {
                w.withSeed(seed);
            } catch (IllegalArgumentException e) {
                refused = e.getMessage();
                assertTrue(refused.contains("could not place k1") && refused.endsWith("(with seed " + seed + ")"),
                        refused);
            }
        }
        assertTrue(refused != null && refused.lines().count() == 1, "a seed that cannot, in one line: " + refused);
    }

    @Test
    void anEntityWithNoPlaceLeftIsOneFaultNamingItAndWhatItHit() throws Exception {
        String m = fault("<distribute><position method=\"constant\" values=\"2,2\"/><entity quantity=\"2\" "
                + "maxTrials=\"5\"><robot name=\"k\" type=\"kilobot\"/></entity></distribute>");
        assertTrue(m.contains("<distribute> number 1 could not place k1 (entity 2 of 2) in 5 tries: the last "
                + "overlapped robot \"k0\""), m);
        m = fault("<distribute><position method=\"grid\" center=\"2,2\" distances=\"1,1\" layout=\"1,1\"/><entity "
                + "quantity=\"2\"><box name=\"b\" width=\"0.1\" depth=\"0.1\"/></entity></distribute>" + ROBOT);
        assertTrue(m.contains("could not place b1 (entity 2 of 2): its grid has no point left"), m);
    }

    @Test
    void aDistributeAtFaultSaysWhatAndWhere() throws Exception {
        assertTrue(fault("<distribute><position method=\"spiral\"/><entity quantity=\"1\"><robot name=\"k\" "
                + "type=\"kilobot\"/></entity></distribute>").contains("<distribute> number 1 <position> method must "
                + "be uniform, gaussian, constant or grid, got \"spiral\""));
        assertTrue(fault("<distribute><position method=\"uniform\" min=\"3,1\" max=\"1,3\"/><entity quantity=\"1\">"
                + "<robot name=\"k\" type=\"kilobot\"/></entity></distribute>").contains("min must not be above max"));
        assertTrue(fault("<distribute><position method=\"constant\" values=\"2,2\"/><orientation method=\"grid\"/>"
                + "<entity quantity=\"1\"><robot name=\"k\" type=\"kilobot\"/></entity></distribute>")
                .contains("<orientation> method \"grid\" places positions only"));
        assertTrue(fault("<distribute><position method=\"constant\" values=\"2,2\"/><entity quantity=\"1\"><robot "
                + "name=\"k\" type=\"kilobot\" x=\"1\"/></entity></distribute>")
                .contains("takes its place from <position> and <orientation>"));
        assertTrue(fault("<distribute><position method=\"constant\" values=\"2,2\"/><entity quantity=\"0\"><robot "
                + "name=\"k\" type=\"kilobot\"/></entity></distribute>").contains("quantity must be in 1..100000, got 0"));
        assertTrue(fault("<distribute><position method=\"constant\" values=\"2,2\"/><entity quantity=\"1\"><robot "
                + "name=\"r\" type=\"kilobot\"/></entity></distribute>" + ROBOT.replace("name=\"r\"", "name=\"r0\""))
                .contains("would name an entity r0, a name already used"));
        assertTrue(fault("<distribute><position method=\"gaussian\" mean=\"2,2\" stdDev=\"x,1\"/><entity "
                + "quantity=\"1\"><robot name=\"k\" type=\"kilobot\"/></entity></distribute>")
                .contains("stdDev must be numbers, got \"x,1\""));
    }
}
