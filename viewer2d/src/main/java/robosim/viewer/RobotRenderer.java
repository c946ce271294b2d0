package robosim.viewer;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Arc2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robosim.devices.SensorInfo;
import robosim.devices.Sensors;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotView;
import robosim.protocol.SensorReading;
import robosim.protocol.SonarSpec;
import robosim.protocol.StepNumbers;

/**
 * Draws one robot as it senses the world: on the left a polar plot in the robot's own frame (heading
 * up, a ring every metre, or every few when it reaches far: at most ten; nothing beyond
 * {@link #MAX_REACH_MM}), its sonar cones filled out to each range and the readings its sensors' kinds show as
 * ranges ({@link Sensors#display}: a laser's) as points; on the right its step, pose, command, contact, tag and only
 * the sensors it has: sonar when its type has any, a reading shown by sides (a bump sensor's: front, left, back,
 * right) and the other readings when its view holds them. A laser's field of view is not on the wire: its
 * beams are drawn at the default resolution of one degree each, centred on the heading. Pure drawing.
 */
public final class RobotRenderer {
    /** The farthest the plot reaches, mm (a value from the network beyond it is not drawn). */
    static final double MAX_REACH_MM = 100_000;
    private static final Color BACKGROUND = new Color(0xF7F8FA);
    private static final Color RING = new Color(0xD5D9E0);
    private static final Color CONE = new Color(31, 119, 180, 70);
    private static final Color LASER = new Color(0xD62728);
    private static final Color TEXT = new Color(0x22262B);

    private RobotRenderer() {
    }

    /** {@code robot}: its index in {@code s}; {@code v}: its newest view, or null. */
    public static void render(Graphics2D g, Scene s, int robot, RobotView v, int width, int height) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(BACKGROUND);
        g.fillRect(0, 0, width, height);
        int plot = Math.max(100, Math.min(height, width - 260));
        polar(g, s, robot, v, plot);
        drawFacts(g, facts(s, robot, v), v, plot + 16);
    }

    private static void polar(Graphics2D g, Scene s, int robot, RobotView v, int size) {
        RobotProperties p = s.robots().get(robot);
        double reach = 1000; // mm: the farthest a sonar or laser reaches, at most MAX_REACH_MM (network values)
        for (SonarSpec spec : p.sonars()) {
            reach = farther(reach, spec.maxRangeMm() + Math.hypot(spec.xMm(), spec.yMm()));
        }
        List<double[]> polar = new ArrayList<>();
        for (SensorReading r : v == null ? List.<SensorReading>of() : v.readings()) {
            if (Sensors.display(r.name(), r.values().length) == SensorInfo.Display.RANGES) {
                polar.add(r.values());
                for (double d : r.values()) {
                    reach = farther(reach, d);
                }
            }
        }
        double cx = size / 2.0;
        double cy = size / 2.0;
        double scale = (size / 2.0 - 12) / reach; // px per mm
        g.setStroke(new BasicStroke(1f));
        g.setColor(RING);
        double ring = 1000 * Math.ceil(reach / 10_000); // (at most ten rings)
        for (double m = ring; m <= reach; m += ring) {
            double r = m * scale;
            g.draw(new Ellipse2D.Double(cx - r, cy - r, 2 * r, 2 * r));
        }
        g.draw(new Line2D.Double(cx, cy - reach * scale, cx, cy + reach * scale));
        g.draw(new Line2D.Double(cx - reach * scale, cy, cx + reach * scale, cy));
        double[] ranges = robot < s.poses().count() ? s.poses().sonarMm(robot) : new double[0];
        for (int k = 0; k < p.sonars().size() && k < ranges.length; k++) {
            SonarSpec spec = p.sonars().get(k);
            // robot frame: x forward (screen up), y left (screen left)
            double ox = cx - spec.yMm() * scale;
            double oy = cy - spec.xMm() * scale;
            if (!(ranges[k] >= 0)) {
                continue; // (NaN from the network)
            }
            double r = Math.min(ranges[k], reach) * scale;
            g.setColor(CONE);
            g.fill(new Arc2D.Double(ox - r, oy - r, 2 * r, 2 * r, 90 + spec.angleDeg() - spec.coneDeg() / 2,
                    spec.coneDeg(), Arc2D.PIE));
        }
        g.setColor(LASER);
        for (double[] values : polar) {
            double first = -(values.length - 1) / 2.0;
            for (int b = 0; b < values.length; b++) {
                if (!(values[b] >= 0 && values[b] <= reach)) {
                    continue;
                }
                double a = Math.toRadians(first + b);
                double x = cx - Math.sin(a) * values[b] * scale;
                double y = cy - Math.cos(a) * values[b] * scale;
                g.fill(new Ellipse2D.Double(x - 1.5, y - 1.5, 3, 3));
            }
        }
        double rr = Math.max(3, p.radiusMm() * scale);
        g.setColor(SceneRenderer.robotColor(robot));
        g.fill(new Ellipse2D.Double(cx - rr, cy - rr, 2 * rr, 2 * rr));
        g.setColor(SceneRenderer.OUTLINE);
        g.draw(new Line2D.Double(cx, cy, cx, cy - rr));
        g.setFont(g.getFont().deriveFont(11f));
        g.drawString(String.format(Locale.ROOT, "1 ring = %.0f m, heading up", ring / 1000), 6, size - 6);
    }

    /**
     * The text beside the plot, a line each: the robot, the step and the run's state, its pose, and of its
     * newest view the command, the sensors it has (sonar when its type has any; the plug-in readings the view
     * holds), contact, tag and messages.
     */
    public static List<String> facts(Scene s, int robot, RobotView v) {
        List<String> lines = new ArrayList<>();
        lines.add(s.names().get(robot) + "  (" + s.robots().get(robot).type() + ")");
        lines.add("step " + StatusLine.step(s) + "   " + StatusLine.state(s));
        if (s.poses().departed().contains(s.names().get(robot))) {
            lines.add("it has left the simulation");
        } else if (s.poses().held().contains(s.names().get(robot))) {
            lines.add("held: lost, standing where it was until it comes back");
        } else if (robot < s.poses().count()) {
            lines.add(String.format(Locale.ROOT, "pose  x %.0f  y %.0f mm  heading %.1f deg", s.poses().xMm(robot),
                    s.poses().yMm(robot), s.poses().headingDeg(robot)));
        }
        if (v != null) {
            lines.add("");
            lines.add(String.format(Locale.ROOT, "command (step %d)  move %.1f mm  turn %.1f deg",
                    StepNumbers.shown(v.step()), v.moveMm(), v.turnDeg()));
            boolean sonars = !s.robots().get(robot).sonars().isEmpty();
            lines.add("  " + (sonars ? "sonar " + (v.askedSonar() ? "asked" : "not asked") + "   " : "") + "tag "
                    + (v.askedTag() ? "asked" : "no"));
            lines.add("contact  " + (v.contact().isEmpty() ? "none" : RobotFeed.clean(v.contact())));
            lines.add("tagged   " + (v.tagged().isEmpty() ? "none" : RobotFeed.clean(v.tagged())));
            for (SensorReading r : v.readings()) {
                lines.add(RobotFeed.clean(r.name()) + "  " + RobotFeed.values(r.values()));
            }
            lines.add("messages: " + v.sent().size() + " sent, " + v.delivered().size() + " delivered"
                    + (v.sinceStep() == v.step() ? "" : " since step " + StepNumbers.shown(v.sinceStep())));
        } else {
            lines.add("");
            lines.add("(waiting for its first step)");
        }
        return lines;
    }

    /** The facts, and under them the bump sensor's sides (lit when touching) when the view holds its reading. */
    private static void drawFacts(Graphics2D g, List<String> lines, RobotView v, int x) {
        g.setColor(TEXT);
        g.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        int y = 20;
        for (String line : lines) {
            g.drawString(line, x, y);
            y += 17;
        }
        SensorReading bump = v == null ? null : bump(v);
        if (bump != null) {
            y += 6;
            List<String> sides = SensorInfo.Display.SIDES_NAMED;
            for (int k = 0; k < sides.size() && k < bump.values().length; k++) {
                boolean hit = bump.values()[k] != 0;
                g.setColor(hit ? LASER : RING);
                g.fillRect(x + k * 62, y, 56, 18);
                g.setColor(hit ? Color.WHITE : TEXT);
                g.drawString(sides.get(k), x + k * 62 + 6, y + 13);
            }
        }
    }

    /** The larger of {@code reach} and {@code d}, at most {@link #MAX_REACH_MM}; a value that is not finite changes nothing. */
    private static double farther(double reach, double d) {
        return Double.isFinite(d) ? Math.min(MAX_REACH_MM, Math.max(reach, d)) : reach;
    }

    /** The first reading its sensor shows by sides (a bump sensor's: front, left, back, right), or null. */
    private static SensorReading bump(RobotView v) {
        for (SensorReading r : v.readings()) {
            if (Sensors.display(r.name(), r.values().length) == SensorInfo.Display.SIDES) {
                return r;
            }
        }
        return null;
    }
}
