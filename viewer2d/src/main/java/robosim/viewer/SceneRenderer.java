package robosim.viewer;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import robosim.protocol.Arena;
import robosim.protocol.Floor;
import robosim.protocol.LedSpec;
import robosim.protocol.Light;
import robosim.protocol.ObstacleShape;
import robosim.protocol.PoseUpdate;
import robosim.protocol.SonarSpec;
import robosim.protocol.WorldObject;

/**
 * Draws a {@link Scene} with a {@link ViewTransform}: arena (its floor: colour, image and painted regions; 1 m grid),
 * obstacles (grey), objects (in their colours; movable ones outlined dashed), lights (a disc of their colour, hollow
 * when off), optional trails and sonar rays, robots (a disc in the robot's colour, a line to the rim along its
 * heading, its LEDs that are lit, its name), and a crimson ring around anything that has been tagged. Pure drawing,
 * no state: the window and the off-screen test use the same code.
 */
public final class SceneRenderer {
    public static final Color OUTSIDE = new Color(0xDDE1E6);
    /** The 1 m grid, translucent: it shows on any floor. */
    public static final Color GRID = new Color(0, 0, 0, 18);
    public static final Color WALL = new Color(0x6B6F76);
    public static final Color OUTLINE = new Color(0x22262B);
    /** The ring around anything that has been tagged. */
    public static final Color TAGGED = new Color(0xE0115F);
    private static final Color[] PALETTE = {
        new Color(0x1F77B4), new Color(0xFF7F0E), new Color(0x2CA02C), new Color(0xD62728), new Color(0x9467BD),
        new Color(0x8C564B), new Color(0xE377C2), new Color(0x17BECF), new Color(0xBCBD22), new Color(0x393B79)};

    /** What to draw besides the world and the robots. */
    public record Options(boolean names, boolean trails, boolean sonar) {
        public static final Options DEFAULT = new Options(true, true, false);
    }

    private SceneRenderer() {
    }

    /** The colour robot {@code i} is drawn in. */
    public static Color robotColor(int i) {
        return PALETTE[i % PALETTE.length];
    }

    public static void render(Graphics2D g, Scene s, ViewTransform t, Options o, int width, int height) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(OUTSIDE);
        g.fillRect(0, 0, width, height);
        drawWorld(g, s, t);
        PoseUpdate poses = s.poses();
        java.util.Set<String> tagged = new java.util.HashSet<>();
        for (String tag : poses.tags()) {
            tagged.add(tag.substring(tag.indexOf('>') + 1));
        }
        if (o.trails()) {
            for (int i = 0; i < s.robotCount(); i++) {
                drawTrail(g, s.trails()[i], t, robotColor(i));
            }
        }
        drawTraces(g, poses.traces(), t);
        if (o.sonar()) {
            for (int i = 0; i < s.robotCount(); i++) {
                drawSonar(g, s.robots().get(i).sonars(), poses, i, t, robotColor(i));
            }
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        java.util.Set<String> gone = new java.util.HashSet<>(poses.departed());
        java.util.Set<String> held = new java.util.HashSet<>(poses.held());
        for (int i = 0; i < s.robotCount(); i++) {
            if (gone.contains(s.names().get(i))) {
                drawGone(g, s, i, t, o.names(), " (left)");
            } else if (held.contains(s.names().get(i))) {
                drawGone(g, s, i, t, o.names(), " (held)");
            } else {
                drawRobot(g, s, i, t, o.names(), tagged.contains(s.names().get(i)));
            }
        }
    }

    /**
     * The world without its robots: the arena's floor and grid, the obstacles (outlined in red where a tag hit them),
     * the objects where the poses put them and the lights (the trajectory plot draws its paths over it).
     */
    public static void drawWorld(Graphics2D g, Scene s, ViewTransform t) {
        drawArena(g, s, t);
        g.setStroke(new BasicStroke(1f));
        java.util.Set<String> tagged = new java.util.HashSet<>();
        for (String tag : s.poses().tags()) {
            tagged.add(tag.substring(tag.indexOf('>') + 1));
        }
        for (ObstacleShape obstacle : s.obstacles()) {
            Path2D p = polygon(obstacle, t);
            g.setColor(WALL);
            g.fill(p);
            boolean hit = tagged.contains(obstacle.name());
            g.setColor(hit ? TAGGED : OUTLINE);
            g.setStroke(new BasicStroke(hit ? 3f : 1f));
            g.draw(p);
        }
        g.setStroke(new BasicStroke(1f));
        drawObjects(g, s, t);
        List<robosim.protocol.Light> file = s.scenery().lights();
        List<robosim.protocol.Light> now = new java.util.ArrayList<>(file.size());
        for (int i = 0; i < file.size(); i++) {
            now.add(s.poses().light(file, i)); // (as the world's loop functions switched it)
        }
        drawLights(g, now, t);
    }

    private static void drawArena(Graphics2D g, Scene s, ViewTransform t) {
        Arena a = s.arena();
        double x0 = t.toScreenX(a.minXMm());
        double y0 = t.toScreenY(a.maxYMm());
        double x1 = t.toScreenX(a.maxXMm());
        double y1 = t.toScreenY(a.minYMm());
        Floor floor = s.scenery().floor();
        g.setColor(new Color(floor.rgb()));
        g.fill(new Rectangle2D.Double(x0, y0, x1 - x0, y1 - y0));
        if (s.floorImage() != null) {
            g.drawImage(s.floorImage(), (int) Math.round(x0), (int) Math.round(y0), (int) Math.round(x1 - x0),
                    (int) Math.round(y1 - y0), null);
        }
        for (Floor.Region r : floor.regions()) {
            g.setColor(new Color(r.rgb()));
            g.fill(region(r.area(), t));
        }
        for (Floor.Region r : s.poses().paint()) { // (what the world's loop functions painted, as of this step)
            g.setColor(new Color(r.rgb()));
            g.fill(region(r.area(), t));
        }
        if (t.scale() * 1000 >= 8) {
            g.setColor(GRID);
            g.setStroke(new BasicStroke(1f));
            for (double x = Math.ceil(a.minXMm() / 1000) * 1000; x <= a.maxXMm(); x += 1000) {
                g.draw(new Line2D.Double(t.toScreenX(x), y0, t.toScreenX(x), y1));
            }
            for (double y = Math.ceil(a.minYMm() / 1000) * 1000; y <= a.maxYMm(); y += 1000) {
                g.draw(new Line2D.Double(x0, t.toScreenY(y), x1, t.toScreenY(y)));
            }
        }
        g.setColor(OUTLINE);
        g.setStroke(new BasicStroke(2f));
        g.draw(new Rectangle2D.Double(x0, y0, x1 - x0, y1 - y0));
    }

    private static java.awt.Shape region(Floor.Area area, ViewTransform t) {
        if (area instanceof Floor.Rectangle r) {
            double x0 = t.toScreenX(r.xMm());
            double y0 = t.toScreenY(r.yMm() + r.heightMm());
            return new Rectangle2D.Double(x0, y0, t.toScreenX(r.xMm() + r.widthMm()) - x0,
                    t.toScreenY(r.yMm()) - y0);
        }
        if (area instanceof Floor.Disc d) {
            double rr = d.radiusMm() * t.scale();
            return new Ellipse2D.Double(t.toScreenX(d.xMm()) - rr, t.toScreenY(d.yMm()) - rr, 2 * rr, 2 * rr);
        }
        return polygon(((Floor.Polygon) area).xyMm(), t);
    }

    /**
     * Each object where the poses put it (its start pose before any), in its colour; a movable one dashed; none the
     * loop functions took out of the world.
     */
    private static void drawObjects(Graphics2D g, Scene s, ViewTransform t) {
        List<WorldObject> objects = s.scenery().objects();
        PoseUpdate p = s.poses();
        boolean moved = p.objectCount() == objects.size();
        double[] corners = new double[8];
        for (int o = 0; o < objects.size(); o++) {
            WorldObject w = objects.get(o);
            if (p.objectGone(o)) {
                continue; // (the world's loop functions took it out)
            }
            double x = moved ? p.objectXMm(o) : w.xMm();
            double y = moved ? p.objectYMm(o) : w.yMm();
            java.awt.Shape shape;
            if (w.shape() == WorldObject.Shape.CYLINDER) {
                double r = w.radiusMm() * t.scale();
                shape = new Ellipse2D.Double(t.toScreenX(x) - r, t.toScreenY(y) - r, 2 * r, 2 * r);
            } else {
                w.corners(x, y, moved ? p.objectHeadingDeg(o) : w.headingDeg(), corners, 0);
                shape = polygon(corners, t);
            }
            g.setColor(new Color(w.rgb()));
            g.fill(shape);
            g.setColor(OUTLINE);
            g.setStroke(w.movable() ? new BasicStroke(1.2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
                    new float[] {3f, 3f}, 0f) : new BasicStroke(1.2f));
            g.draw(shape);
        }
        g.setStroke(new BasicStroke(1f));
    }

    /** Each light: a disc of its colour (at least 8 pixels across), hollow when it is off. */
    private static void drawLights(Graphics2D g, List<Light> lights, ViewTransform t) {
        for (Light l : lights) {
            double r = Math.max(4, 60 * t.scale());
            Ellipse2D disc = new Ellipse2D.Double(t.toScreenX(l.xMm()) - r, t.toScreenY(l.yMm()) - r, 2 * r, 2 * r);
            if (l.shines()) {
                Color c = new Color(l.rgb());
                g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), 70));
                g.fill(new Ellipse2D.Double(disc.getX() - r, disc.getY() - r, 4 * r, 4 * r));
                g.setColor(c);
                g.fill(disc);
            }
            g.setColor(OUTLINE);
            g.draw(disc);
        }
    }

    private static Path2D polygon(double[] xy, ViewTransform t) {
        Path2D.Double p = new Path2D.Double();
        p.moveTo(t.toScreenX(xy[0]), t.toScreenY(xy[1]));
        for (int v = 2; v < xy.length; v += 2) {
            p.lineTo(t.toScreenX(xy[v]), t.toScreenY(xy[v + 1]));
        }
        p.closePath();
        return p;
    }

    private static Path2D polygon(ObstacleShape o, ViewTransform t) {
        Path2D.Double p = new Path2D.Double();
        p.moveTo(t.toScreenX(o.x(0)), t.toScreenY(o.y(0)));
        for (int v = 1; v < o.vertexCount(); v++) {
            p.lineTo(t.toScreenX(o.x(v)), t.toScreenY(o.y(v)));
        }
        p.closePath();
        return p;
    }

    private static void drawTrail(Graphics2D g, double[] trail, ViewTransform t, Color c) {
        if (trail.length < 4) {
            return;
        }
        Path2D.Double p = new Path2D.Double();
        p.moveTo(t.toScreenX(trail[0]), t.toScreenY(trail[1]));
        for (int k = 2; k < trail.length; k += 2) {
            p.lineTo(t.toScreenX(trail[k]), t.toScreenY(trail[k + 1]));
        }
        g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), 90));
        g.setStroke(new BasicStroke(1.5f));
        g.draw(p);
    }

    /**
     * What the loop functions drew ({@code drawing}, whole, as {@link SceneFeed} gives it; a piece alone, which holds
     * points of traces begun before it, is not drawn): each trace a line of its colour.
     */
    private static void drawTraces(Graphics2D g, robosim.protocol.Traces drawing, ViewTransform t) {
        if (!drawing.fresh() || drawing.traces() == 0) {
            return;
        }
        Path2D.Double[] lines = new Path2D.Double[drawing.traces()];
        int last = drawing.firstPoint() + drawing.points();
        for (int p = drawing.firstPoint(); p < last; p++) {
            int k = drawing.traceOf(p);
            double x = t.toScreenX(drawing.xMm(p));
            double y = t.toScreenY(drawing.yMm(p));
            if (lines[k] == null) {
                lines[k] = new Path2D.Double();
                lines[k].moveTo(x, y);
            } else {
                lines[k].lineTo(x, y);
            }
        }
        g.setStroke(new BasicStroke(2f));
        for (int k = 0; k < lines.length; k++) {
            if (lines[k] != null) {
                g.setColor(new Color(drawing.rgb(k)));
                g.draw(lines[k]);
            }
        }
    }

    private static void drawSonar(Graphics2D g, List<SonarSpec> sonars, PoseUpdate poses, int i, ViewTransform t,
            Color c) {
        double[] ranges = poses.sonarMm(i);
        if (ranges.length != sonars.size()) {
            return;
        }
        double h = Math.toRadians(poses.headingDeg(i));
        double cos = Math.cos(h);
        double sin = Math.sin(h);
        g.setStroke(new BasicStroke(1f));
        for (int k = 0; k < ranges.length; k++) {
            SonarSpec s = sonars.get(k);
            double ox = poses.xMm(i) + s.xMm() * cos - s.yMm() * sin;
            double oy = poses.yMm(i) + s.xMm() * sin + s.yMm() * cos;
            double axis = h + Math.toRadians(s.angleDeg());
            double half = Math.toRadians(s.coneDeg() / 2);
            double r = ranges[k];
            Path2D.Double cone = new Path2D.Double();
            cone.moveTo(t.toScreenX(ox), t.toScreenY(oy));
            cone.lineTo(t.toScreenX(ox + r * Math.cos(axis - half)), t.toScreenY(oy + r * Math.sin(axis - half)));
            cone.lineTo(t.toScreenX(ox + r * Math.cos(axis + half)), t.toScreenY(oy + r * Math.sin(axis + half)));
            cone.closePath();
            g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), r < s.maxRangeMm() ? 45 : 18));
            g.fill(cone);
        }
    }

    /** A robot that has left the simulation: a dashed outline where it was last, and "(left)". */
    /** A robot drawn dashed, not filled: one that has left, or one held for its return ({@code label} says). */
    private static void drawGone(Graphics2D g, Scene s, int i, ViewTransform t, boolean names, String label) {
        PoseUpdate p = s.poses();
        double r = s.robots().get(i).radiusMm() * t.scale();
        double cx = t.toScreenX(p.xMm(i));
        double cy = t.toScreenY(p.yMm(i));
        g.setColor(OUTLINE);
        g.setStroke(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {4f, 4f}, 0f));
        g.draw(new Ellipse2D.Double(cx - r, cy - r, 2 * r, 2 * r));
        if (names && r >= 3) {
            g.drawString(s.names().get(i) + label, (float) (cx + r + 2), (float) (cy - r - 2));
        }
    }

    /** A robot's lit LEDs, each a dot of its colour where it sits on the robot (above the body: drawn over it). */
    private static void drawLeds(Graphics2D g, List<LedSpec> where, int[] colours, double cx, double cy, double h,
            ViewTransform t) {
        double dot = Math.max(2, 12 * t.scale());
        double c = Math.cos(h);
        double sn = Math.sin(h);
        for (int k = 0; k < Math.min(where.size(), colours.length); k++) {
            if (colours[k] == 0) {
                continue;
            }
            LedSpec l = where.get(k);
            double lx = cx + (l.xMm() * c - l.yMm() * sn) * t.scale();
            double ly = cy - (l.xMm() * sn + l.yMm() * c) * t.scale();
            Ellipse2D led = new Ellipse2D.Double(lx - dot, ly - dot, 2 * dot, 2 * dot);
            g.setColor(new Color(colours[k]));
            g.fill(led);
            g.setColor(OUTLINE);
            g.setStroke(new BasicStroke(0.8f));
            g.draw(led);
        }
    }

    private static void drawRobot(Graphics2D g, Scene s, int i, ViewTransform t, boolean names, boolean tagged) {
        PoseUpdate p = s.poses();
        double r = s.robots().get(i).radiusMm() * t.scale();
        double cx = t.toScreenX(p.xMm(i));
        double cy = t.toScreenY(p.yMm(i));
        if (tagged) {
            g.setColor(TAGGED);
            g.setStroke(new BasicStroke(3f));
            g.draw(new Ellipse2D.Double(cx - r - 4, cy - r - 4, 2 * r + 8, 2 * r + 8));
        }
        Ellipse2D body = new Ellipse2D.Double(cx - r, cy - r, 2 * r, 2 * r);
        g.setColor(robotColor(i));
        g.fill(body);
        g.setColor(OUTLINE);
        g.setStroke(new BasicStroke(1.2f));
        g.draw(body);
        double h = Math.toRadians(p.headingDeg(i));
        g.setStroke(new BasicStroke(2f));
        g.draw(new Line2D.Double(cx, cy, cx + r * Math.cos(h), cy - r * Math.sin(h)));
        drawLeds(g, s.robots().get(i).leds(), p.leds(i), cx, cy, h, t);
        if (names && r >= 3) {
            g.drawString(s.names().get(i), (float) (cx + r + 2), (float) (cy - r - 2));
        }
    }
}
