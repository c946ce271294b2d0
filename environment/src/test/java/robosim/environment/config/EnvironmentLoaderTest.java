package robosim.environment.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.environment.core.WorldSpec;

/**
 * Environment files: a good one loads with units converted; each fault of a bad one is one line naming where it is and
 * what is wrong, every fault of the file at once.
 */
class EnvironmentLoaderTest {
    @TempDir
    Path dir;

    private Path write(String xml) throws IOException {
        Path f = dir.resolve("env.xml");
        Files.writeString(f, xml);
        return f;
    }

    private static String env(String attrs, String body) {
        return "<environment " + attrs + "><arena width=\"10\" height=\"5\"/>" + body + "</environment>";
    }

    private static final String ROBOT = "<robots><robot name=\"r1\" type=\"ArRobot\" control=\"x.Y\" x=\"1\" y=\"1\" "
            + "heading=\"90\"/></robots>";

    private String failure(String xml) throws IOException {
        Path f = write(xml);
        EnvironmentFileException e = assertThrows(EnvironmentFileException.class, () -> new EnvironmentLoader().load(f));
        assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
        assertTrue(e.getMessage().startsWith(f.toString()), "names the file: " + e.getMessage());
        return e.getMessage();
    }

    /** The lines of the refusal of {@code f}, one per fault. */
    private static List<String> faults(Path f) {
        return assertThrows(EnvironmentFileException.class, () -> new EnvironmentLoader().load(f)).getMessage().lines()
                .toList();
    }

    @Test
    void loadsTheBundledEnvironments() throws Exception {
        WorldSpec test = new EnvironmentLoader().load(Path.of("../test-envs/test.xml"));
        assertEquals(500, test.timeStepMs());
        assertEquals(2, test.robots().size());
        assertEquals("robot1", test.robots().get(0).name());
        assertEquals(1500, test.robots().get(0).xMm());
        assertEquals(13_000, test.arena().maxXMm());
        assertEquals(2, test.obstacles().size());
        assertEquals(10, new EnvironmentLoader().load(Path.of("../test-envs/paper-benchmark.xml")).robots().size());
        assertEquals(6, new EnvironmentLoader().load(Path.of("../test-envs/maze.xml")).robots().size());
        assertEquals(100, new EnvironmentLoader().load(Path.of("../test-envs/swarm-100.xml")).robots().size());
        assertEquals(4, new EnvironmentLoader().load(Path.of("../test-envs/follow.xml")).robots().size());
        assertEquals(4, new EnvironmentLoader().load(Path.of("../test-envs/tag.xml")).robots().size());
        WorldSpec sensors = new EnvironmentLoader().load(Path.of("../test-envs/sensors.xml"));
        assertEquals(3, sensors.robots().size());
        assertEquals(List.of("laser", "heat", "bump"), sensors.robots().get(1).sensorNames());
        for (int n : new int[] {10, 100, 1000}) {
            assertEquals(n, new EnvironmentLoader().load(Path.of("../test-envs/bench-" + n + ".xml")).robots().size());
        }
    }

    @Test
    void convertsMetresToMillimetresAndKeepsObstacleOrder() throws Exception {
        WorldSpec s = new EnvironmentLoader().load(write(env("timeStepMs=\"100\"",
                "<obstacles><polygon name=\"p\" points=\"5,1 6,1 5.5,2\"/><rectangle name=\"r\" x=\"7\" y=\"3\" "
                        + "width=\"1\" height=\"0.5\"/></obstacles>" + ROBOT)));
        assertEquals(100, s.timeStepMs());
        assertEquals("p", s.obstacles().get(0).name());
        assertEquals(6000, s.obstacles().get(0).x(1));
        assertEquals("r", s.obstacles().get(1).name());
        assertEquals(3500, s.obstacles().get(1).y(2));
        assertEquals(90, s.robots().get(0).headingDeg());
    }

    @Test
    void aMissingFile() {
        Path f = dir.resolve("nope.xml");
        EnvironmentFileException e = assertThrows(EnvironmentFileException.class, () -> new EnvironmentLoader().load(f));
        assertEquals(f + ": file not found", e.getMessage());
    }

    @Test
    void malformedXmlNamesTheLine() throws Exception {
        String m = failure("<environment timeStepMs=\"500\">\n<arena width=\"1\" height=\"1\">\n</environment>");
        assertTrue(m.contains("malformed XML"), m);
        assertTrue(m.matches(".*env\\.xml:3:\\d+: .*"), m);
    }

    @Test
    void anUnknownRobotType() throws Exception {
        String m = failure(env("timeStepMs=\"500\"",
                "<robots><robot name=\"r1\" type=\"Roomba\" x=\"1\" y=\"1\"/></robots>"));
        assertTrue(m.endsWith("<robot name=\"r1\"> type \"Roomba\" is not a known robot type (known: "
                + robosim.devices.RobotTypes.names() + ", or the class name of a RobotType with radius=\"...\")"), m);
    }

    @Test
    void aNegativeTimeStep() throws Exception {
        String m = failure(env("timeStepMs=\"-5\"", ROBOT));
        assertTrue(m.endsWith("<environment> timeStepMs must be > 0, got -5"), m);
    }

    @Test
    void aTimeStepThatIsNotANumber() throws Exception {
        String m = failure(env("timeStepMs=\"fast\"", ROBOT));
        assertTrue(m.contains("timeStepMs") && m.contains("'fast'"), m);
    }

    @Test
    void anUnknownAttribute() throws Exception {
        String m = failure(env("timeStepMs=\"500\" colour=\"red\"", ROBOT));
        assertTrue(m.contains("unknown element or attribute 'colour'"), m);
    }

    @Test
    void joinRulesAreReadAndChecked() throws Exception {
        WorldSpec swarm = new EnvironmentLoader().load(Path.of("../test-envs/swarm-join.xml"));
        assertEquals(List.of("keeper1", "keeper2"), swarm.robots().stream().map(WorldSpec.RobotSpec::name).toList(),
                "an any-time robot is not waited for at the start");
        assertEquals(List.of("late", "scout-*"), swarm.joins().stream().map(robosim.environment.core.JoinRule::allow)
                .toList());
        assertTrue(swarm.joinRule("scout-17").matches("scout-17"));
        assertEquals(30, swarm.joinRule("scout-17").max());
        assertEquals(null, swarm.joinRule("scoutx"));
        assertEquals(14_500, swarm.joinRule("late").template().xMm());
        String join = "<join allow=\"s-?\" type=\"Scout\" max=\"3\"><spawn x=\"1\" y=\"1\" width=\"2\" "
                + "height=\"2\"/></join>";
        assertTrue(new EnvironmentLoader().load(write(env("timeStepMs=\"500\"", ROBOT + join))).joinRule("s-1") != null);
        for (String[] bad : new String[][] {
                {join.replace("allow=\"s-?\" ", ""), "<join> number 1 needs allow=\"...\""},
                {join.replace("max=\"3\"", "max=\"0\""), "<join allow=\"s-?\"> needs max=\"N\", from 1"},
                {join.replace("width=\"2\"", "width=\"20\""), "<join allow=\"s-?\"> <spawn> must lie inside the arena"},
                {join.replace("<spawn x=\"1\" y=\"1\" width=\"2\" height=\"2\"/>", ""), "needs a <spawn"},
                {join.replace("Scout", "Hover"), "type \"Hover\" is not a known robot type"},
                {join + join, "the pattern is used twice"},
                {join.replace("s-?", "s ?"), "a pattern is 1 to 64 letters, digits, - _ . : and the wildcards"}}) {
            String m = failure(env("timeStepMs=\"500\"", ROBOT + bad[0]));
            assertTrue(m.contains(bad[1]), m);
        }
        String m = failure(env("timeStepMs=\"500\"", ROBOT.replace("heading=\"90\"", "join=\"later\"")));
        assertTrue(m.endsWith("join must be \"any-time\" (or left out: there from the start), got \"later\""), m);
        m = failure(env("timeStepMs=\"500\"", ROBOT.replace("heading=\"90\"", "join=\"any-time\"")));
        assertTrue(m.contains("must name at least one <robot> there from the start"), m);
        m = failure(env("timeStepMs=\"500\"", ROBOT.replace("</robots>", "<robot name=\"late one\" type=\"Scout\" "
                + "x=\"5\" y=\"3\" join=\"any-time\"/></robots>")));
        assertTrue(m.contains("a robot that joins needs a name of 1 to 64 letters"), m);
    }

    @Test
    void duplicateRobotNames() throws Exception {
        String m = failure(env("timeStepMs=\"500\"", "<robots><robot name=\"r1\" type=\"ArRobot\" x=\"1\" y=\"1\"/>"
                + "<robot name=\"r1\" type=\"ArRobot\" x=\"3\" y=\"1\"/></robots>"));
        assertTrue(m.endsWith("<robot name=\"r1\"> the name is used twice"), m);
    }

    @Test
    void aRobotOverlappingAnObstacleOrOutsideTheArena() throws Exception {
        String m = failure(env("timeStepMs=\"500\"", "<obstacles><rectangle name=\"wall\" x=\"1.1\" y=\"0\" width=\"1\" "
                + "height=\"5\"/></obstacles>" + ROBOT));
        assertTrue(m.endsWith("overlaps obstacle \"wall\""), m);
        m = failure(env("timeStepMs=\"500\"", "<robots><robot name=\"r1\" type=\"ArRobot\" x=\"0.1\" y=\"1\"/></robots>"));
        assertTrue(m.contains("does not fit inside the arena"), m);
    }

    @Test
    void aSelfCrossingPolygon() throws Exception {
        String m = failure(env("timeStepMs=\"500\"",
                "<obstacles><polygon name=\"bow\" points=\"5,1 6,2 6,1 5,2\"/></obstacles>" + ROBOT));
        assertTrue(m.endsWith("<polygon name=\"bow\"> points do not form a simple polygon (edges cross or repeat)"), m);
    }

    @Test
    void messagingSettingsAreReadAndChecked() throws Exception {
        WorldSpec s = new EnvironmentLoader().load(write(env("timeStepMs=\"500\" commRangeM=\"2.5\" maxMessageBytes=\"100\"",
                ROBOT)));
        assertEquals(2500, s.commRangeMm());
        assertEquals(100, s.maxMessageBytes());
        assertEquals(WorldSpec.DEFAULT_MAX_MESSAGE_BYTES,
                new EnvironmentLoader().load(write(env("timeStepMs=\"500\"", ROBOT))).maxMessageBytes());
        assertTrue(failure(env("timeStepMs=\"500\" commRangeM=\"-1\"", ROBOT))
                .endsWith("<environment> commRangeM must be > 0 m, got -1.0"));
        assertTrue(failure(env("timeStepMs=\"500\" maxMessageBytes=\"70000\"", ROBOT))
                .endsWith("<environment> maxMessageBytes must be in 1..65535, got 70000"));
        assertTrue(failure(env("timeStepMs=\"500\"", "<robots><robot name=\"*\" type=\"ArRobot\" x=\"1\" y=\"1\"/>"
                + "</robots>")).endsWith("\"*\" is reserved: it addresses every robot"));
    }

    @Test
    void sensorsAndHeatSourcesAreReadAndChecked() throws Exception {
        WorldSpec s = new EnvironmentLoader().load(write(env("timeStepMs=\"500\"",
                "<heatSources><heat name=\"fire\" x=\"5\" y=\"2\" intensity=\"10\"/></heatSources>"
                        + "<robots><robot name=\"r1\" type=\"ArRobot\" x=\"1\" y=\"1\" sonarNoiseMm=\"15\">"
                        + "<sensor name=\"front\" type=\"laser\" fovDeg=\"90\" noise=\"5\"/><sensor type=\"bump\"/>"
                        + "</robot></robots>")));
        assertEquals(List.of(new robosim.devices.HeatSource("fire", 5000, 2000, 10)), s.heatSources());
        WorldSpec.RobotSpec r = s.robots().get(0);
        assertEquals(List.of("front", "bump"), r.sensorNames());
        assertEquals(java.util.Map.of("fovDeg", "90", "noise", "5"), r.sensors().get(0).attributes());
        assertEquals(15, r.sonarNoiseMm());

        String m = failure(env("timeStepMs=\"500\"", "<robots><robot name=\"r1\" type=\"ArRobot\" x=\"1\" y=\"1\">"
                + "<sensor type=\"sniffer\"/></robot></robots>"));
        assertTrue(m.endsWith("<robot name=\"r1\"> <sensor name=\"sniffer\"> type \"sniffer\" is neither "
                + robosim.devices.Sensors.fileNames() + " nor a class on the class path"), m);
        m = failure(env("timeStepMs=\"500\"", "<robots><robot name=\"r1\" type=\"ArRobot\" x=\"1\" y=\"1\">"
                + "<sensor type=\"laser\" fov=\"90\"/></robot></robots>"));
        assertTrue(m.contains("unknown attribute(s) [fov] for a laser sensor (it takes: fovDeg, "), m);
        m = failure(env("timeStepMs=\"500\"", "<robots><robot name=\"r1\" type=\"ArRobot\" x=\"1\" y=\"1\">"
                + "<sensor type=\"laser\" noise=\"-1\"/></robot></robots>"));
        assertTrue(m.endsWith("noise must be >= 0, got -1.0"), m);
        m = failure(env("timeStepMs=\"500\"", "<heatSources><heat name=\"h\" x=\"1\" y=\"1\"/></heatSources>" + ROBOT));
        assertTrue(m.endsWith("<heat name=\"h\"> needs the attribute intensity"), m);
    }

    @Test
    void aRobotTypeClassNeedsItsRadiusAndAKnownModelsRadiusMustAgree() throws Exception {
        String m = failure(env("timeStepMs=\"500\"", "<robots><robot name=\"h\" type=\"com.example.Hexapod\" x=\"1\" "
                + "y=\"1\"/></robots>"));
        assertTrue(m.endsWith("a robot of type class com.example.Hexapod needs radius=\"...\" (metres)"), m);
        WorldSpec s = new EnvironmentLoader().load(write(env("timeStepMs=\"500\"", "<robots><robot name=\"h\" "
                + "type=\"com.example.Hexapod\" radius=\"0.3\" sonars=\"6\" x=\"1\" y=\"1\"/></robots>")));
        assertEquals(300, s.robots().get(0).radiusMm());
        assertEquals(6, s.robots().get(0).sonarCount());
        m = failure(env("timeStepMs=\"500\"", "<robots><robot name=\"a\" type=\"ArRobot\" radius=\"0.3\" x=\"1\" "
                + "y=\"1\"/></robots>"));
        assertTrue(m.endsWith("radius 0.3 m contradicts the ArRobot's 0.25 m"), m);
    }

    @Test
    void missingArenaAndNoRobots() throws Exception {
        assertTrue(failure("<environment timeStepMs=\"500\">" + ROBOT + "</environment>").contains("needs an <arena"));
        assertTrue(failure(env("timeStepMs=\"500\"", "")).contains("needs at least one robot"));
    }

    @Test
    void everyFaultOfAFileIsReportedAtOnceInFileOrderEachWithItsLineAndColumn() throws Exception {
        // heat sources are checked after the robots, and the unknown attribute is found while the file is read,
        // before any check: the lines come in file order all the same
        Path f = write("""
                <environment timeStepMs="500">
                  <arena width="10" height="5"/>
                  <heatSources>
                      <heat name="h" x="1" y="1"/>
                  </heatSources>
                  <robots>
                    <robot name="r1" type="Roomba" x="1" y="1"/>  <robot name="r2" type="Scout" x="5" y="3" colour="red"/>
                  </robots>
                </environment>
                """);
        List<String> lines = faults(f);
        assertEquals(3, lines.size(), String.join("\n", lines));
        assertEquals(f + ":4:7: <heat name=\"h\"> needs the attribute intensity", lines.get(0));
        assertEquals(f + ":7:5: <robot name=\"r1\"> type \"Roomba\" is not a known robot type (known: "
                + robosim.devices.RobotTypes.names() + ", or the class name of a RobotType with radius=\"...\")", lines.get(1));
        assertTrue(lines.get(2).startsWith(f + ":7:51: unknown element or attribute 'colour' (known here: ["),
                lines.get(2));
    }

    @Test
    void aFaultAfterAPlaceholderOnItsLineIsAtTheFilesColumnNotTheReplacedTexts() throws Exception {
        Path f = write("""
                <environment timeStepMs="500">
                  <arena width="${w:10}" height="5"/>
                  <robots>
                    <robot name="${n:r1}" type="ArRobot" x="1" y="1"/> <robot name="r2" type="Hover" x="5" y="3"/>
                  </robots>
                </environment>
                """);
        List<String> lines = faults(f);
        assertEquals(1, lines.size(), String.join("\n", lines));
        assertTrue(lines.get(0).startsWith(f + ":4:56: <robot name=\"r2\"> type \"Hover\""), lines.get(0));
        // the same with a longer value given for the placeholder: the file's column still
        EnvironmentFileException e = assertThrows(EnvironmentFileException.class,
                () -> new EnvironmentLoader().load(f, java.util.Map.of("n", "a-much-longer-name")));
        assertTrue(e.getMessage().startsWith(f + ":4:56: <robot name=\"r2\"> type \"Hover\""), e.getMessage());
    }

    @Test
    void aNameOfMegabytesIsCutInEveryFaultThatNamesIt() throws Exception {
        String name = "n".repeat(400_000);
        StringBuilder params = new StringBuilder();
        for (int i = 0; i < 30; i++) {
            params.append("<param/>");
        }
        Path f = write("<environment timeStepMs=\"500\"><arena width=\"10\" height=\"5\"/><robots>\n<robot name=\""
                + name + "\" type=\"ArRobot\" x=\"1\" y=\"1\">" + params + "</robot></robots></environment>");
        List<String> lines = faults(f);
        assertEquals(FileFaults.SHOWN + 1, lines.size(), lines.get(0));
        assertTrue(lines.stream().allMatch(l -> l.length() < 400), "each line names the robot cut: " + lines.get(0));
        assertTrue(lines.get(0).contains("<robot name=\"" + "n".repeat(64) + "...\">"), lines.get(0));
    }

    @Test
    void theFirstTwentyFaultsInFileOrderAreShownThenHowManyMore() throws Exception {
        StringBuilder robots = new StringBuilder();
        for (int i = 1; i <= 25; i++) {
            robots.append("<robot name=\"r").append(i).append("\" type=\"Hover\" x=\"1\" y=\"1\"/>\n");
        }
        // the heat source is checked last, but it comes first in the file
        Path f = write("<environment timeStepMs=\"500\"><arena width=\"10\" height=\"5\"/>\n<heatSources><heat x=\"1\" "
                + "y=\"1\" intensity=\"-1\"/></heatSources>\n<robots>\n" + robots + "</robots></environment>");
        List<String> lines = faults(f);
        assertEquals(FileFaults.SHOWN + 1, lines.size(), String.join("\n", lines));
        assertEquals(f + ":2:14: <heat name=\"heat1\"> intensity must be >= 0, got -1.0", lines.get(0));
        for (int i = 1; i < FileFaults.SHOWN; i++) {
            assertTrue(lines.get(i).startsWith(f + ":" + (i + 3) + ":1: <robot name=\"r" + i + "\"> type \"Hover\""),
                    lines.get(i));
        }
        assertEquals("... and 6 more", lines.get(FileFaults.SHOWN));
    }

    @Test
    void malformedXmlEndsTheReadingAfterTheFaultsFoundBeforeIt() throws Exception {
        Path f = write("<environment timeStepMs=\"500\" colour=\"red\">\n<arena width=\"1\" height=\"1\">\n"
                + "</environment>");
        List<String> lines = faults(f);
        assertEquals(2, lines.size(), String.join("\n", lines));
        assertTrue(lines.get(0).startsWith(f + ":1:1: unknown element or attribute 'colour'"), lines.get(0));
        assertTrue(lines.get(1).matches(".*env\\.xml:3:\\d+: malformed XML: .*"), lines.get(1));
    }

    @Test
    void aValueNotOfItsTypeIsOneFaultAndAValueWithALineBreakStaysOnItsFaultsLine() throws Exception {
        Path f = write(env("timeStepMs=\"500\"", "\n<robots><robot name=\"r1\" type=\"Arr&#10;obot\" x=\"one\" "
                + "y=\"1\"/></robots>"));
        List<String> lines = faults(f);
        assertEquals(2, lines.size(), String.join("\n", lines));
        assertEquals(f + ":2:9: x value 'one' is not a double", lines.get(0), "not also \"needs the attribute x\"");
        assertTrue(lines.get(1).startsWith(f + ":2:9: <robot name=\"r1\"> type \"Arr?obot\" is not a known robot "
                + "type"), lines.get(1));
    }

    @Test
    void xsiNilIsAnUnknownAttributeNotAMissingElement() throws Exception {
        Path f = write("<environment timeStepMs=\"500\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n"
                + "<arena width=\"10\" height=\"5\"/><obstacles><rectangle name=\"box\" x=\"5\" y=\"2\" width=\"1\" "
                + "height=\"1\" xsi:nil=\"true\"/></obstacles>\n<robots><robot name=\"r1\" type=\"ArRobot\" x=\"1\" "
                + "y=\"1\"><sensor type=\"laser\" xsi:nil=\"true\"/></robot></robots>\n</environment>");
        List<String> lines = faults(f);
        assertEquals(2, lines.size(), String.join("\n", lines));
        assertTrue(lines.get(0).startsWith(f + ":2:42: unknown element or attribute 'nil'"), lines.get(0));
        assertTrue(lines.get(1).startsWith(f + ":3:53: <robot name=\"r1\"> <sensor name=\"laser\"> unknown attribute(s) "
                + "[nil] for a laser sensor (it takes: "), lines.get(1));
    }
}
