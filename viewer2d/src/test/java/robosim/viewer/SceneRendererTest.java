package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.Floor;
import robosim.protocol.LedSpec;
import robosim.protocol.Light;
import robosim.protocol.ObstacleShape;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;
import robosim.protocol.Scenery;
import robosim.protocol.WorldObject;

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
        assertEquals(robosim.protocol.Floor.PLAIN.rgb(), pixel(img, t, 1500, 4500));
        assertEquals(rgb(SceneRenderer.OUTSIDE), img.getRGB(3, 3) & 0xFFFFFF);
        // where robot a is not: floor
        assertEquals(robosim.protocol.Floor.PLAIN.rgb(), pixel(img, t, 3500, 3500));
    }

    @Test
    void whatTheLoopFunctionsDrewIsDrawnInItsColour() {
        robosim.protocol.Traces.Log drawing = new robosim.protocol.Traces.Log();
        drawing.add("path", 500, 4500, 0xFF0000);
        drawing.add("path", 3500, 4500, 0xFF0000);
        Scene plain = scene();
        PoseUpdate drew = plain.poses().withExperiment(List.of(), List.of(), List.of(), drawing.since(),
                drawing.whole(), new int[0]).posesOnly();
        Scene s = new Scene(ARENA, plain.obstacles(), plain.names(), plain.robots(), drew, plain.trails(), 0,
                plain.status());
        BufferedImage img = new BufferedImage(1000, 500, BufferedImage.TYPE_INT_RGB);
        ViewTransform t = new ViewTransform();
        t.fit(ARENA, 1000, 500);
        Graphics2D g = img.createGraphics();
        SceneRenderer.render(g, s, t, SceneRenderer.Options.DEFAULT, 1000, 500);
        g.dispose();
        int x = (int) Math.round(t.toScreenX(2000));
        int y = (int) Math.floor(t.toScreenY(4500));
        assertTrue(close(0xFF0000, img.getRGB(x, y) & 0xFFFFFF, 40) || close(0xFF0000, img.getRGB(x, y + 1) & 0xFFFFFF,
                40), "on the trace (a 2-pixel line, its edges anti-aliased)");
        assertEquals(robosim.protocol.Floor.PLAIN.rgb(), pixel(img, t, 4000, 4500), "beyond its end");
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
        assertEquals(robosim.protocol.Floor.PLAIN.rgb(), pixel(img, t, 2000 - (250 + 4 / t.scale()), 2500));
    }

    @Test
    void theFloorObjectsLightsAndLitLedsAreDrawnWhereTheyStand() {
        // a grey floor with a black disc painted at (1, 1) m, a red box pushed from (3, 1) to (3.5, 1) m, a yellow
        // light at (9, 4) m, and robot a with a green LED at its front (its second LED off)
        Floor floor = new Floor(0x808080, List.of(new Floor.Region(new Floor.Disc(1000, 1000, 400), 0)), null);
        WorldObject box = new WorldObject("crate", WorldObject.Shape.BOX, 600, 600, 200, 1, 0.5, true, false, 0xFF0000,
                3000, 1000, 0);
        Light light = new Light("lamp", 9000, 4000, 1000, 0xFFFF00, 3, true);
        RobotProperties withLeds = new RobotProperties("Led", 250, 250, 10, 1000, 300, List.of(), List.of(),
                List.of(new LedSpec(200, 0, 100), new LedSpec(-200, 0, 100)), null);
        PoseUpdate poses = new PoseUpdate(41, new double[] {2000}, new double[] {2500}, new double[] {0})
                .withScene(new double[] {3500}, new double[] {1000}, new double[] {0}, new int[][] {{0x00FF00, 0}});
        Scene s = new Scene(ARENA, List.of(), List.of("a"), List.of(withLeds), poses, new double[][] {{}}, 0,
                ViewedRun.of(ViewedRun.Kind.RUNNING), new Scenery(floor, List.of(light), List.of(box)), null);
        BufferedImage img = new BufferedImage(1000, 500, BufferedImage.TYPE_INT_RGB);
        ViewTransform t = new ViewTransform();
        t.fit(ARENA, 1000, 500);
        Graphics2D g = img.createGraphics();
        SceneRenderer.render(g, s, t, SceneRenderer.Options.DEFAULT, 1000, 500);
        g.dispose();
        assertEquals(0x808080, pixel(img, t, 6500, 2500), "the floor's colour");
        assertEquals(0, pixel(img, t, 1100, 1100), "the painted disc");
        assertEquals(0xFF0000, pixel(img, t, 3700, 1000), "the box where it was pushed to");
        assertEquals(0x808080, pixel(img, t, 2850, 1000), "not where it started");
        assertEquals(0xFFFF00, pixel(img, t, 9000, 4000), "the light");
        assertEquals(0x00FF00, pixel(img, t, 2200, 2500), "the lit LED");
        assertEquals(rgb(SceneRenderer.robotColor(0)), pixel(img, t, 1800, 2500 + 60), "the unlit one: the body");
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
