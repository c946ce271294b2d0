package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * A short seeded soak in the suite, every part its own process, as {@code scripts/soak.sh} runs it: ring robots
 * of two processes over shared connections, a silent robot, one robot process and the Geometry process killed
 * mid-run (the step waits for the new one, so that a run this short sees it attach), garbage on every port,
 * viewers that come and go and one that never reads; every step runs, every
 * message between robots there to the end arrives once and in order, each surviving robot reports, and the
 * heap stays flat ({@link SoakReport}). Its report is in this test's output.
 */
class SoakTest {
    @Test
    void aShortSeededSoakPasses() {
        int exit = new CommandLine(new Soak()).execute("--robots", "6", "--robot-processes", "2", "--silent-robots",
                "1", "--steps", "1000", "--seed", "5", "--on-geometry-loss", "WAIT");
        assertEquals(0, exit, "soak: FAIL (its report is in the test's output)");
    }
}
