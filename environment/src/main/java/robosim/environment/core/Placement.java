package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;
import robosim.protocol.WorldObject;

/**
 * What has been placed so far, for the check of the next robot or object placed: the arena, the obstacles, and the
 * objects and robots placed before (an environment file's, in file order, then each {@code <distribute>}'s; or the
 * world as it stands, where loop functions move one). Says what a new one would overlap (interiors, touching allowed),
 * the first found, or null where it fits.
 */
public final class Placement {
    private final GeometryFactory jts = new GeometryFactory();
    private final Arena arena;
    private final List<ObstacleShape> obstacles;
    private final List<Geometry> walls = new ArrayList<>();
    private final List<WorldObject> objects = new ArrayList<>();
    /** Each placed object's outline: a box's polygon, a cylinder's centre (its radius is the object's). */
    private final List<Geometry> outlines = new ArrayList<>();
    private final List<String> robotNames = new ArrayList<>();
    private final List<double[]> robots = new ArrayList<>();

    /** {@code arena} may be null (at fault: nothing is outside it). */
    public Placement(Arena arena, List<ObstacleShape> obstacles) {
        this.arena = arena;
        this.obstacles = List.copyOf(obstacles);
        for (ObstacleShape o : obstacles) {
            walls.add(Obstacles.polygon(o));
        }
    }

    /**
     * What a round body at (x, y) of {@code radius} would overlap, the first of: outside the arena, an obstacle, an
     * object, a robot ({@code "obstacle \"wall\""}); null where it fits.
     */
    public String overlapOfDisc(double x, double y, double radius) {
        if (arena != null && (x - radius < arena.minXMm() || x + radius > arena.maxXMm()
                || y - radius < arena.minYMm() || y + radius > arena.maxYMm())) {
            return "the arena's edge";
        }
        Geometry centre = jts.createPoint(new Coordinate(x, y));
        for (int o = 0; o < walls.size(); o++) {
            if (walls.get(o).distance(centre) < radius) {
                return "obstacle \"" + cut(obstacles.get(o).name()) + "\"";
            }
        }
        for (int o = 0; o < objects.size(); o++) {
            WorldObject other = objects.get(o);
            double reach = other.shape() == WorldObject.Shape.CYLINDER ? radius + other.radiusMm() : radius;
            if (outlines.get(o).distance(centre) < reach) {
                return "object \"" + cut(other.name()) + "\"";
            }
        }
        for (int r = 0; r < robots.size(); r++) {
            double[] other = robots.get(r);
            if (Math.hypot(other[0] - x, other[1] - y) < radius + other[2]) {
                return "robot \"" + cut(robotNames.get(r)) + "\"";
            }
        }
        return null;
    }

    /** What {@code object} at its pose would overlap, as {@link #overlapOfDisc} says it; null where it fits. */
    public String overlapOf(WorldObject object) {
        if (object.shape() == WorldObject.Shape.CYLINDER) {
            return overlapOfDisc(object.xMm(), object.yMm(), object.radiusMm());
        }
        Geometry box = outline(object);
        if (arena != null && !jts.toGeometry(new org.locationtech.jts.geom.Envelope(arena.minXMm(), arena.maxXMm(),
                arena.minYMm(), arena.maxYMm())).covers(box)) {
            return "the arena's edge";
        }
        for (int o = 0; o < walls.size(); o++) {
            if (overlap(walls.get(o), box)) {
                return "obstacle \"" + cut(obstacles.get(o).name()) + "\"";
            }
        }
        for (int o = 0; o < objects.size(); o++) {
            WorldObject other = objects.get(o);
            boolean hit = other.shape() == WorldObject.Shape.CYLINDER
                    ? box.distance(outlines.get(o)) < other.radiusMm() : overlap(outlines.get(o), box);
            if (hit) {
                return "object \"" + cut(other.name()) + "\"";
            }
        }
        for (int r = 0; r < robots.size(); r++) {
            double[] other = robots.get(r);
            if (box.distance(jts.createPoint(new Coordinate(other[0], other[1]))) < other[2]) {
                return "robot \"" + cut(robotNames.get(r)) + "\"";
            }
        }
        return null;
    }

    private static String cut(String name) {
        return robosim.protocol.Printable.of(name, 64);
    }

    private static boolean overlap(Geometry a, Geometry b) {
        return a.intersects(b) && !a.touches(b);
    }

    private Geometry outline(WorldObject o) {
        if (o.shape() == WorldObject.Shape.CYLINDER) {
            return jts.createPoint(new Coordinate(o.xMm(), o.yMm()));
        }
        double[] c = o.corners();
        return jts.createPolygon(new Coordinate[] {new Coordinate(c[0], c[1]), new Coordinate(c[2], c[3]),
            new Coordinate(c[4], c[5]), new Coordinate(c[6], c[7]), new Coordinate(c[0], c[1])});
    }

    public void addRobot(String name, double x, double y, double radius) {
        robotNames.add(name);
        robots.add(new double[] {x, y, radius});
    }

    public void addObject(WorldObject object) {
        objects.add(object);
        outlines.add(outline(object));
    }
}
