package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;
import robosim.protocol.PoseUpdate;

/** The viewer's drawing, off-screen, from a known scene: pixels where robots and walls must be. */
class SceneRendererTest {
    private static final Arena ARENA = new Arena(0, 0, 10_000, 5_000);
    private static final ObstacleShape BOX = ObstacleShape.rectangle("box", 4000, 1000, 2000, 1000);

    private static Scene scene() {
        PoseUpdate poses = new PoseUpdate(41, new double[] {2000, 8000}, new double[] {2500, 4000},
                new double[] {0, 90});
        return new Scene(ARENA, List.of(BOX), List.of("a", "b"), List.of(robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("Scout")),
                poses, new double[][] {{}, {}}, 0, ViewedRun.of(ViewedRun.Kind.RUNNING));
    }

    private static int pixel(BufferedImage img, ViewTransform t, double xMm, double yMm) {
        return img.getRGB((int) Math.round(t.toScreenX(xMm)), (int) Math.round(t.toScreenY(yMm))) & 0xFFFFFF;
    }

    /** Each channel within {@code tolerance}: the 3-pixel ring's edges are anti-aliased. */
    private static boolean close(int expected, int actual, int tolerance) {
        for (int shift = 0; shift <= 16; shift += 8) {
            if (Math.abs(((expected >> shift) & 0xFF) - ((actual >> shift) & 0xFF)) > tolerance) {
                return false;
            }
        }
        return true;
    }

    private static int rgb(Color c) {
        return c.getRGB() & 0xFFFFFF;
    }

    @Test
    void robotsWallsFloorAndOutsideAreWhereTheWorldSays() {
        int w = 1000;
        int h = 500;
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        ViewTransform t = new ViewTransform();
        t.fit(ARENA, w, h);
        Graphics2D g = img.createGraphics();
        SceneRenderer.render(g, scene(), t, SceneRenderer.Options.DEFAULT, w, h);
        g.dispose();

        // the scale fits 10 m x 5 m into 1000 x 500 with a 12 px margin: 476 / 5000 px per mm
        assertEquals(476.0 / 5000, t.scale(), 1e-12);
        // inside each robot's disc, beside its heading line
        assertEquals(rgb(SceneRenderer.robotColor(0)), pixel(img, t, 2000, 2500 + 120));
        assertEquals(rgb(SceneRenderer.robotColor(1)), pixel(img, t, 8000 - 100, 4000));
        // the heading line of robot a runs from its centre to the rim along +x
        assertEquals(rgb(SceneRenderer.OUTLINE), pixel(img, t, 2000 + 150, 2500));
        // inside the box, on the open floor, and outside the arena
        assertEquals(rgb(SceneRenderer.WALL), pixel(img, t, 5000, 1500));
        assertEquals(rgb(SceneRenderer.FLOOR), pixel(img, t, 1500, 4500));
        assertEquals(rgb(SceneRenderer.OUTSIDE), img.getRGB(3, 3) & 0xFFFFFF);
        // where robot a is not: floor
        assertEquals(rgb(SceneRenderer.FLOOR), pixel(img, t, 3500, 3500));
    }

    @Test
    void aTaggedRobotGetsARing() {
        PoseUpdate poses = new PoseUpdate(41, new double[] {2000, 8000}, new double[] {2500, 4000},
                new double[] {0, 90}, null, List.of("a>b"));
        Scene s = new Scene(ARENA, List.of(BOX), List.of("a", "b"), List.of(robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("Scout")),
                poses, new double[][] {{}, {}}, 0, ViewedRun.of(ViewedRun.Kind.RUNNING));
        BufferedImage img = new BufferedImage(1000, 500, BufferedImage.TYPE_INT_RGB);
        ViewTransform t = new ViewTransform();
        t.fit(ARENA, 1000, 500);
        Graphics2D g = img.createGraphics();
        SceneRenderer.render(g, s, t, SceneRenderer.Options.DEFAULT, 1000, 500);
        g.dispose();
        // b (radius 190 mm) gets a ring 4 px outside its rim; a does not
        double ringMm = 190 + 4 / t.scale();
        int ring = pixel(img, t, 8000 + ringMm, 4000);
        assertTrue(close(rgb(SceneRenderer.TAGGED), ring, 24), "the ring's colour (anti-aliased): "
                + Integer.toHexString(ring));
        assertEquals(rgb(SceneRenderer.FLOOR), pixel(img, t, 2000 - (250 + 4 / t.scale()), 2500));
    }

    @Test
    void zoomKeepsThePointUnderTheCursorAndFitCentresTheArena() {
        ViewTransform t = new ViewTransform();
        t.fit(ARENA, 1000, 500);
        assertEquals(500, t.toScreenX(5000), 1e-9);
        assertEquals(250, t.toScreenY(2500), 1e-9);
        double wx = t.toWorldX(300);
        double wy = t.toWorldY(200);
        t.zoomAt(300, 200, 2.5);
        assertEquals(wx, t.toWorldX(300), 1e-9);
        assertEquals(wy, t.toWorldY(200), 1e-9);
        t.pan(10, -5);
        assertEquals(wx, t.toWorldX(310), 1e-9);
    }
}
