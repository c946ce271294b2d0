package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.examples.Wander;

/** {@code record-tool.sh plot}: a recording's trajectories drawn over the arena, to scale, in a PNG. */
class TrajectoryPlotTest {
    @TempDir
    Path dir;

    @Test
    void aRecordingsTrajectoriesAreAPngOfTheArenaWithAColourForEachRobot() throws Exception {
        Path recording = dir.resolve("run.rec");
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("wander.xml"))
                .settings(s -> s.record(recording)).run(200, true, Wander::new);
        assertTrue(sim.summary.completed(), sim.summary.reason());
        Path png = dir.resolve("paths.png");
        assertEquals(0, new picocli.CommandLine(new RecordToolMain()).execute("plot", recording.toString(), "--out",
                png.toString(), "--size", "400"));
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(500, image.getWidth(), "the 8 m square arena 400 px, and a margin of 50 around it");
        assertEquals(500, image.getHeight());
        Set<Integer> colours = new HashSet<>();
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                colours.add(image.getRGB(x, y) & 0xffffff);
            }
        }
        for (int robot : new int[] {0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x8c564b}) {
            assertTrue(colours.contains(robot), "robot colour " + Integer.toHexString(robot) + " drawn");
        }
        assertTrue(colours.contains(robosim.viewer.SceneRenderer.WALL.getRGB() & 0xffffff), "the obstacles drawn, as the "
                + "viewers draw them");
        assertEquals(2, new picocli.CommandLine(new RecordToolMain()).execute("plot", recording.toString(), "--out",
                png.toString()), "an existing file is not overwritten");
        assertTrue(Files.size(png) > 2000);

        Path turns = dir.resolve("turns.png");
        assertEquals(0, new picocli.CommandLine(new RecordToolMain()).execute("plot", recording.toString(), "--report",
                "turns", "--out", turns.toString()));
        assertEquals(800, ImageIO.read(turns.toFile()).getWidth(), "Wander's turns over the run");
        assertEquals(1, new picocli.CommandLine(new RecordToolMain()).execute("plot", recording.toString(), "--report",
                "turnz", "--out", dir.resolve("none.png").toString()), "a name no robot reported");
    }
}
