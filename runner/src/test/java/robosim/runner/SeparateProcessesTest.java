package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** headless.sh for real: Environment, Geometry and 3 robots as separate OS processes, 200 steps. */
class SeparateProcessesTest {
    @TempDir
    Path dir;

    @Test
    void threeRobotProcessesFor200Steps() throws Exception {
        Path log = dir.resolve("poses.csv");
        PrintStream saved = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int code;
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        try {
            code = new CommandLine(new HeadlessRunner()).execute("--env", "src/test/resources/three-robots.xml",
                    "--steps", "200", "--pose-log", log.toString(), "--timeout-s", "120", "--profile",
                    dir.resolve("profile").toString());
        } finally {
            System.setOut(saved);
        }
        List<String> lines = out.toString(StandardCharsets.UTF_8).lines().toList();
        assertEquals(0, code, String.join("\n", lines));
        String last = lines.get(lines.size() - 1);
        assertTrue(last.matches("steps=200 robots=3 wall_s=[0-9.]+ steps_per_s=[0-9.]+ robot_steps_per_s=[0-9.]+ .*"
                + "geometry=process robots_in=processes"), last);

        List<String> rows = Files.readAllLines(log);
        assertEquals("step,robot,x_m,y_m,heading_deg,state", rows.get(0));
        assertEquals(1 + 200 * 3, rows.size(), "one row per robot per step");
        // 200 steps = 2 cycles of 88 + 24 steps forward: x = 1.5 + 24 * 0.25 m
        double[] expected = BackAndForthMath.after(199);
        assertEquals(6.0, expected[0] / 1000);
        assertEquals("199,r1,7.5,1.0,0.0,running", rows.get(rows.size() - 3));
        assertEquals("199,r2,7.5,2.0,0.0,running", rows.get(rows.size() - 2));
        assertEquals("199,r3,7.5,3.0,0.0,running", rows.get(rows.size() - 1));
        assertTrue(Files.size(dir.resolve("profile/environment.jfr")) > 0, "--profile recorded the Environment");
        assertTrue(Files.size(dir.resolve("profile/geometry.jfr")) > 0, "--profile recorded Geometry");
    }

    @Test
    void aBadEnvironmentFileExits2() {
        PrintStream saved = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        int code;
        try {
            code = new CommandLine(new HeadlessRunner()).execute("--env", "missing.xml", "--steps", "10");
        } finally {
            System.setErr(saved);
        }
        assertEquals(2, code);
        assertEquals("missing.xml: file not found", err.toString(StandardCharsets.UTF_8).strip());
    }
}
