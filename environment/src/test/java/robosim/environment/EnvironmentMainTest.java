package robosim.environment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * The Environment's command line: bad input exits 2 with one line naming what is wrong (a bad file: a line per fault).
 */
class EnvironmentMainTest {
    private record Result(int code, String err) {
    }

    private static Result run(String... args) {
        PrintStream saved = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            CommandLine cl = new CommandLine(new EnvironmentMain());
            cl.setParameterExceptionHandler((ex, a) -> 2);
            return new Result(cl.execute(args), err.toString(StandardCharsets.UTF_8));
        } finally {
            System.setErr(saved);
        }
    }

    @Test
    void aMissingFileExits2() {
        Result r = run("no-such-file.xml");
        assertEquals(2, r.code());
        assertEquals("no-such-file.xml: file not found", r.err().strip());
    }

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.CsvSource(delimiter = '|', value = {
        "<environment timeStepMs='500'><arena width='5' height='5'><robots></environment>|malformed XML",
        "<environment timeStepMs='500'><arena width='5' height='5'/><robots><robot name='a' type='Roomba' x='1' y='1'/></robots></environment>|<robot name=\"a\"> type \"Roomba\" is not a known robot type",
        "<environment timeStepMs='-500'><arena width='5' height='5'/><robots><robot name='a' type='ArRobot' x='1' y='1'/></robots></environment>|<environment> timeStepMs must be > 0, got -500"})
    void badFilesExit2WithOneLine(String xml, String expected, @org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        java.nio.file.Path f = dir.resolve("bad.xml");
        java.nio.file.Files.writeString(f, xml);
        Result r = run(f.toString());
        assertEquals(2, r.code());
        String line = r.err().strip();
        assertTrue(line.startsWith(f.toString()) && line.contains(expected) && !line.contains("\n"), line);
    }

    @Test
    void aFileWithSeveralFaultsExits2WithEachOnItsOwnLine(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        java.nio.file.Path f = dir.resolve("bad.xml");
        java.nio.file.Files.writeString(f, "<environment timeStepMs='-500'>\n<arena width='5' height='5'/>\n<robots>\n"
                + "<robot name='a' type='Roomba' x='1' y='1'/>\n<robot name='a' type='ArRobot' x='3' y='1'/>\n"
                + "</robots></environment>");
        Result r = run(f.toString());
        assertEquals(2, r.code());
        assertEquals(java.util.List.of(f + ":1:1: <environment> timeStepMs must be > 0, got -500",
                f + ":4:1: <robot name=\"a\"> type \"Roomba\" is not a known robot type (known: "
                        + robosim.devices.RobotTypes.names() + ", or the "
                        + "class name of a RobotType with radius=\"...\")",
                f + ":5:1: <robot name=\"a\"> the name is used twice"), r.err().strip().lines().toList());
    }

    @Test
    void aPortInUseIsNamed() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            int port = taken.getLocalPort();
            Result r = run("../test-envs/test.xml", "--robot-port", Integer.toString(port), "--viewer-port", "0",
                    "--geometry-port", "0", "--control-port", "0");
            assertEquals(2, r.code());
            assertTrue(r.err().strip().endsWith("robot port " + port
                    + " is already in use (choose another with the --*-port options)"), r.err());
        }
    }

    @Test
    void listeningBeyondLoopbackNeedsTheSimulationKeys() throws Exception {
        // (a developer who exported keys, as the README says, would start a real Environment here)
        org.junit.jupiter.api.Assumptions.assumeTrue(System.getenv("ROBOSIM_KEYS") == null, "keys are set in this shell");
        for (String control : new String[] {"0", "-1"}) {
            Result r = run("../test-envs/test.xml", "--bind", "0.0.0.0", "--robot-port", "0", "--viewer-port", "0",
                    "--geometry-port", "0", "--control-port", control);
            assertEquals(2, r.code());
            assertEquals("environment: --bind 0.0.0.0 opens every port beyond this machine: set ROBOSIM_KEYS to a "
                    + "directory made by scripts/make-keys.sh (TLS and the shared secret) for every process",
                    r.err().strip());
        }
    }

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.CsvSource(delimiter = '|', value = {
        "f.xml|1.0", "f.xml --steps 500|0.0", "f.xml --speed 0|0.0", "f.xml --speed 2.5|2.5",
        "f.xml --steps 500 --speed 4|4.0"})
    void aSessionWithoutStepsRunsInRealTimeUnlessSpeedSaysOtherwise(String args, double expected) {
        EnvironmentMain main = new EnvironmentMain();
        new CommandLine(main).parseArgs(args.split(" "));
        assertEquals(expected, main.run.speed(main.steps));
    }

    @Test
    void helpExitsZero() {
        PrintStream saved = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        try {
            assertEquals(0, new CommandLine(new EnvironmentMain()).execute("--help"));
        } finally {
            System.setOut(saved);
        }
        assertTrue(out.toString(StandardCharsets.UTF_8).contains("--no-geometry"));
    }
}
