package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.CommEvent;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotView;
import robosim.protocol.SensorReading;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;

/**
 * The robot-specific viewer: its feed's log of messages and notices, its drawing, off-screen, and its facts, which
 * name only the sensors the robot has.
 */
class RobotViewerTest {
    private static final Arena ARENA = new Arena(0, 0, 10_000, 5_000);

    private static RobotView view(long step, double[] laser, double[] bump, List<CommEvent> sent,
            List<CommEvent> delivered, List<String> notices) {
        StepRequest q = new StepRequest(step, 250, 0, true, sent, List.of("laser", "bump"));
        StepResponse r = new StepResponse(step, 250, 0, "", 0, 0, 0, new double[0], delivered, notices,
                List.of(new SensorReading("laser", laser), new SensorReading("bump", bump)));
        return RobotView.of(step, 0, "a", q, r);
    }

    private static double[] filled(int n, double v) {
        double[] a = new double[n];
        Arrays.fill(a, v);
        return a;
    }

    @Test
    void theFeedLogsWhatTheRobotSentAndGotAndSaysWhatItSkipped() {
        RobotFeed feed = new RobotFeed("a");
        feed.snapshot(new WorldSnapshot(500, ARENA, List.of(), List.of("a", "b"),
                List.of(robosim.devices.RobotTypes.properties("Scout"), robosim.devices.RobotTypes.properties("Scout")), new PoseUpdate(-1, new double[2], new double[2], new double[2])));
        assertNull(feed.view());
        RobotView first = view(3, filled(181, 2000), new double[4], List.of(new CommEvent("", "b", "ping\u0007")),
                List.of(new CommEvent("b", "a", "pong")), List.of("b is out of range"));
        RobotView merged = view(9, filled(181, 2000), new double[4], List.of(), List.of(), List.of()).after(first);
        feed.robotView(merged);
        assertEquals(merged, feed.view());
        List<String> log = feed.log();
        // steps as every display numbers them: the wire's steps 3 to 9 are the 4th to the 10th (protocol/README.md)
        assertEquals(List.of("-- watching a in a run of 2 robots", "steps 4-10  out  to b: ping?",
                "steps 4-10  in   from b: pong", "steps 4-10  notice: b is out of range"), log);
        for (int k = 0; k < RobotFeed.LOG_LINES + 10; k++) {
            feed.robotView(view(10 + k, filled(181, 2000), new double[4], List.of(new CommEvent("", "b", "" + k)),
                    List.of(), List.of()));
        }
        assertEquals(RobotFeed.LOG_LINES, feed.log().size(), "the newest lines, bounded");
        assertEquals("step " + (10 + RobotFeed.LOG_LINES + 10) + "  out  to b: " + (RobotFeed.LOG_LINES + 9),
                feed.log().get(RobotFeed.LOG_LINES - 1));
        assertEquals(RobotFeed.MAX_TEXT + 3, RobotFeed.clean("x".repeat(5000)).length(), "network text is cut");
    }

    @Test
    void theRobotIsDrawnAsItSensesTheWorld() {
        double[] sonar = new double[16];
        sonar[1] = 3000; // (only the sonar 22.5 degrees to the left of the heading sees something)
        PoseUpdate poses = new PoseUpdate(41, new double[] {2000, 8000}, new double[] {2500, 4000},
                new double[] {30, 90}, new double[][] {sonar, {}});
        Scene scene = new Scene(ARENA, List.of(), List.of("a", "b"), List.of(robosim.devices.RobotTypes.properties("Scout"), robosim.devices.RobotTypes.properties("Scout")),
                poses, new double[][] {{}, {}}, 0, ViewedRun.of(ViewedRun.Kind.RUNNING));
        double[] laser = filled(181, 3000);
        Arrays.fill(laser, 0, 10, 1000); // (its rightmost beams, 90 to 81 degrees right of the heading, see close)
        int w = 900;
        int h = 500;
        RobotView at41 = view(41, laser, new double[] {1, 0, 0, 0}, List.of(), List.of(), List.of());
        List<String> facts = RobotRenderer.facts(scene, 0, at41);
        assertTrue(facts.get(1).startsWith("step 42   RUNNING"), "after wire step 41: 42 steps completed, as the status "
                + "line says: " + facts.get(1));
        assertTrue(facts.contains("command (step 42)  move 250.0 mm  turn 0.0 deg"), facts.toString());
        assertTrue(StatusLine.text(scene).startsWith("step 42 "), StatusLine.text(scene));
        BufferedImage front = draw(scene, at41, w, h);
        double scale = (h / 2.0 - 12) / (5000 + 190); // the plot fills the height; its reach: a sonar's
        int cx = h / 2;
        int cy = h / 2;
        assertEquals(SceneRenderer.robotColor(0).getRGB() & 0xFFFFFF, front.getRGB(cx + 3, cy + 3) & 0xFFFFFF,
                "the robot at the centre");
        double right = Math.toRadians(85);
        assertTrue(reddish(front, (int) Math.round(cx + Math.sin(right) * 1000 * scale),
                (int) Math.round(cy - Math.cos(right) * 1000 * scale)), "the laser's first beams: right, 1 m");
        assertFalse(reddish(front, (int) Math.round(cx - Math.sin(right) * 1000 * scale),
                (int) Math.round(cy - Math.cos(right) * 1000 * scale)), "not left: its last beams read 3 m");
        double a = Math.toRadians(22.5);
        int inCone = front.getRGB((int) Math.round(cx - Math.sin(a) * 1500 * scale),
                (int) Math.round(cy - Math.cos(a) * 1500 * scale)) & 0xFFFFFF;
        assertTrue((inCone & 0xFF) > ((inCone >> 16) & 0xFF), "inside sonar 1's cone, 22.5 deg left: blue, got "
                + Integer.toHexString(inCone));
        assertEquals(0xF7F8FA, front.getRGB((int) Math.round(cx + Math.sin(a) * 1500 * scale),
                (int) Math.round(cy - Math.cos(a) * 1500 * scale)) & 0xFFFFFF, "22.5 deg right: no cone");
        assertEquals(0xF7F8FA, front.getRGB((int) Math.round(cx - Math.sin(a) * 4500 * scale),
                (int) Math.round(cy - Math.cos(a) * 4500 * scale)) & 0xFFFFFF, "beyond its 3 m range: nothing");
        int box = h + 16; // (the facts begin beside the plot; the bump boxes are 62 px apart, 56 wide)
        assertTrue(laserRed(front, box, box + 56), "the front bump lit");
        assertFalse(laserRed(front, box + 56, w), "and no other");
        BufferedImage left = draw(scene, view(41, laser, new double[] {0, 1, 0, 0}, List.of(), List.of(), List.of()), w, h);
        assertFalse(laserRed(left, box, box + 56), "front not lit");
        assertTrue(laserRed(left, box + 62, box + 62 + 56), "the left bump lit");
    }

    @Test
    void theFactsNameOnlyTheSensorsTheRobotHas() {
        RobotProperties noSonar = new RobotProperties("Crawler", 200, 500, 90, List.of());
        Scene scene = new Scene(ARENA, List.of(), List.of("a", "b"), List.of(noSonar, robosim.devices.RobotTypes.properties("Scout")),
                new PoseUpdate(7, new double[] {2000, 8000}, new double[] {2500, 4000}, new double[] {0, 90}),
                new double[][] {{}, {}}, 0, ViewedRun.of(ViewedRun.Kind.RUNNING));
        StepRequest q = new StepRequest(7, 100, 0, false, List.of(), List.of("heat"));
        StepResponse r = new StepResponse(7, 100, 0, "", 0, 0, 0, new double[0], List.of(), List.of(),
                List.of(new SensorReading("heat", new double[] {21.5})));
        String crawler = String.join("\n", RobotRenderer.facts(scene, 0, RobotView.of(7, 0, "a", q, r)));
        assertFalse(crawler.contains("sonar"), "no sonar on a type without any: " + crawler);
        assertTrue(crawler.contains("\nheat  21.5\n"), "the heat sensor it read: " + crawler);
        assertFalse(crawler.contains("bump") || crawler.contains("laser"), "nothing it has not: " + crawler);
        String scout = String.join("\n", RobotRenderer.facts(scene, 1, RobotView.of(7, 1, "b", q, r)));
        assertTrue(scout.contains("  sonar not asked   tag no"), "a Scout's sonar: " + scout);
    }

    private static BufferedImage draw(Scene s, RobotView v, int w, int h) {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        RobotRenderer.render(g, s, 0, v, w, h);
        g.dispose();
        return img;
    }

    /** A pixel within 2 of (x, y) that is mostly red. */
    private static boolean reddish(BufferedImage img, int x, int y) {
        for (int dy = -2; dy <= 2; dy++) {
            for (int dx = -2; dx <= 2; dx++) {
                int p = img.getRGB(x + dx, y + dy);
                if (((p >> 16) & 0xFF) > ((p >> 8) & 0xFF) + 80) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Any pixel from column {@code from} up to {@code to} in the laser/bump red exactly. */
    private static boolean laserRed(BufferedImage img, int from, int to) {
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = from; x < to; x++) {
                if ((img.getRGB(x, y) & 0xFFFFFF) == 0xD62728) {
                    return true;
                }
            }
        }
        return false;
    }
}
