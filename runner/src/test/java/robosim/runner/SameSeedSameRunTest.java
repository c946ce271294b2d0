package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** Two runs of the maze (noisy sonar, seed 42), robots as separate processes: identical pose logs. */
class SameSeedSameRunTest {
    @TempDir
    Path dir;

    private Path run(String name) {
        Path log = dir.resolve(name);
        int code = new CommandLine(new HeadlessRunner()).execute("--env", "../test-envs/maze.xml", "--steps", "300",
                "--pose-log", log.toString(), "--timeout-s", "120");
        assertEquals(0, code);
        return log;
    }

    @Test
    void theSameSeedGivesTheSamePoseLog() throws Exception {
        byte[] first = Files.readAllBytes(run("first.csv"));
        byte[] second = Files.readAllBytes(run("second.csv"));
        assertEquals(1 + 300 * 6, new String(first).lines().count());
        assertTrue(java.util.Arrays.equals(first, second), "the two pose logs differ");
    }
}
