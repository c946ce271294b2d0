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

/** The Environment's command line: bad input exits 2 with one line naming what is wrong. */
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

    @Test
    void aPortInUseIsNamed() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            int port = taken.getLocalPort();
            Result r = run("../test-envs/test.xml", "--robot-port", Integer.toString(port), "--viewer-port", "0",
                    "--geometry-port", "0");
            assertEquals(2, r.code());
            assertTrue(r.err().strip().endsWith("robot port " + port
                    + " is already in use (choose another with the --*-port options)"), r.err());
        }
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
