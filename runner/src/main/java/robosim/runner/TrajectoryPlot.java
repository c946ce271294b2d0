package robosim.runner;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import robosim.protocol.Arena;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.WorldSnapshot;

/**
 * A recording's trajectories as a PNG ({@code record-tool.sh plot FILE --out FILE.png}): the world as the viewers draw
 * it (its floor, its obstacles in grey, its objects where the run left them, its lights), and each robot's path over the whole run in a colour of its own, a hollow circle where it stood before the
 * first step and a filled one where it stood after the last, its name beside that; north (+y) up, metres on the
 * edges, drawn to scale. Headless (Java 2D into an image).
 */
final class TrajectoryPlot {
    /** The plot's margin around the arena, px. */
    private static final int MARGIN = 50;
    private static final Color[] COLOURS = {new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c),
        new Color(0xff7f0e), new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x17becf),
        new Color(0xbcbd22), new Color(0x7f7f7f)};

    private TrajectoryPlot() {
    }

    /** Draws {@code recording}'s trajectories into {@code png} (a new file), the arena's longer side {@code sizePx}. */
    static void draw(RecordingReader recording, Path png, int sizePx) throws IOException {
        WorldSnapshot world = recording.snapshot();
        Arena arena = world.arena();
        double widthMm = arena.maxXMm() - arena.minXMm();
        double heightMm = arena.maxYMm() - arena.minYMm();
        double scale = sizePx / Math.max(widthMm, heightMm); // px per mm
        int w = (int) Math.ceil(widthMm * scale) + 2 * MARGIN;
        int h = (int) Math.ceil(heightMm * scale) + 2 * MARGIN;
        List<Path2D.Double> paths = new ArrayList<>();
        List<String> names = new ArrayList<>(world.robotNames());
        PoseUpdate start = world.poses();
        for (int r = 0; r < start.count(); r++) {
            Path2D.Double p = new Path2D.Double();
            p.moveTo(start.xMm(r), start.yMm(r));
            paths.add(p);
        }
        for (int i = 0; i < recording.steps(); i++) {
            PoseUpdate u = recording.step(i).update();
            for (int r = 0; r < u.count(); r++) {
                if (r >= paths.size()) { // (a robot that joined: its path starts where it first stands)
                    Path2D.Double p = new Path2D.Double();
                    p.moveTo(u.xMm(r), u.yMm(r));
                    paths.add(p);
                } else {
                    paths.get(r).lineTo(u.xMm(r), u.yMm(r));
                }
            }
        }
        if (recording.steps() > 0) {
            names = new ArrayList<>(recording.snapshotAt(recording.steps() - 1).robotNames());
        }
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, w, h);
            // world (mm, +y north) to image (px, +y down); the world as it ended: floor, obstacles, objects, lights
            robosim.viewer.ViewTransform view = new robosim.viewer.ViewTransform();
            view.fit(arena, w, h, MARGIN);
            java.awt.geom.AffineTransform toImage = new java.awt.geom.AffineTransform(view.scale(), 0, 0,
                    -view.scale(), view.toScreenX(0), view.toScreenY(0));
            PoseUpdate end = recording.steps() > 0 ? recording.step(recording.steps() - 1).update() : start;
            robosim.viewer.SceneRenderer.drawWorld(g, new robosim.viewer.Scene(arena, world.obstacles(), names,
                    world.robots(), end.count() == 0 ? start : end, new double[0][], Double.NaN,
                    robosim.viewer.ViewedRun.of(robosim.viewer.ViewedRun.Kind.STOPPED), world.scenery(),
                    robosim.viewer.Scene.picture(world.scenery().floor().image())), view);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
            g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            for (int r = 0; r < paths.size(); r++) {
                Color colour = COLOURS[r % COLOURS.length];
                g.setColor(colour);
                g.draw(toImage.createTransformedShape(paths.get(r)));
                double[] first = new double[2];
                double[] last = new double[2];
                ends(paths.get(r), first, last);
                java.awt.geom.Point2D a = toImage.transform(new java.awt.geom.Point2D.Double(first[0], first[1]), null);
                java.awt.geom.Point2D b = toImage.transform(new java.awt.geom.Point2D.Double(last[0], last[1]), null);
                g.draw(new Ellipse2D.Double(a.getX() - 5, a.getY() - 5, 10, 10));
                g.fill(new Ellipse2D.Double(b.getX() - 5, b.getY() - 5, 10, 10));
                g.drawString(r < names.size() ? names.get(r) : "robot " + r, (float) b.getX() + 7, (float) b.getY() - 7);
            }
            g.setColor(Color.BLACK);
            g.drawString(String.format(java.util.Locale.ROOT, "%.1f m", arena.minXMm() / 1000), MARGIN - 10, h - MARGIN + 18);
            g.drawString(String.format(java.util.Locale.ROOT, "%.1f m", arena.maxXMm() / 1000), w - MARGIN - 20,
                    h - MARGIN + 18);
            g.drawString(String.format(java.util.Locale.ROOT, "%.1f m", arena.maxYMm() / 1000), 4, MARGIN + 4);
            g.drawString(recording.steps() + " steps, " + paths.size() + " robots: start o, end \u25cf", MARGIN,
                    MARGIN - 18);
        } finally {
            g.dispose();
        }
        Path temporary = png.resolveSibling("." + png.getFileName() + ".tmp-" + ProcessHandle.current().pid());
        if (!ImageIO.write(image, "png", temporary.toFile())) {
            throw new IOException("no PNG writer in this JDK");
        }
        Files.move(temporary, png, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
    }

    /** The first and the last point of {@code path}. */
    private static void ends(Path2D path, double[] first, double[] last) {
        double[] c = new double[6];
        boolean got = false;
        for (java.awt.geom.PathIterator i = path.getPathIterator(null); !i.isDone(); i.next()) {
            i.currentSegment(c);
            if (!got) {
                first[0] = c[0];
                first[1] = c[1];
                got = true;
            }
            last[0] = c[0];
            last[1] = c[1];
        }
    }
}
