package robosim.environment.config;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import robosim.protocol.ObstacleShape;

/**
 * The {@code <obstacles>} of an environment file (rectangles and simple polygons, metres to millimetres,
 * names unique) and the checked numbers every part of the file reads; each fault is recorded as one line naming the
 * element and what is wrong, at the element.
 */
final class ObstacleReader {
    private static final double MM_PER_M = 1000.0;

    /**
     * The obstacles that could be read, in file order, the names of those a robot's tag can hit, and every name the
     * obstacles take (objects may not take them too).
     */
    record Obstacles(List<ObstacleShape> shapes, Set<String> taggable, Set<String> names) {
    }

    private ObstacleReader() {
    }

    /**
     * A number {@code element} must have, finite; null, its fault recorded, when it has none or one not finite (or
     * one not a number: that fault was recorded as it was read).
     */
    static Double required(FileFaults faults, FileElement element, String label, String attribute, Double v) {
        if (v == null) {
            if (!element.hadBadValue(attribute)) {
                faults.add(element.at, label + " needs the attribute " + attribute);
            }
            return null;
        }
        if (!Double.isFinite(v)) {
            faults.add(element.at, label + " " + attribute + " must be a finite number, got " + v);
            return null;
        }
        return v;
    }

    /**
     * Every obstacle whose shape could be read (one that could not is left out, its fault recorded, so no robot is
     * checked against it).
     */
    static Obstacles obstacles(FileFaults faults, EnvironmentFile xml) {
        List<ObstacleShape> out = new ArrayList<>();
        Set<String> taggable = new HashSet<>();
        Set<String> names = new HashSet<>();
        for (int i = 0; i < xml.obstacles.all.size(); i++) {
            FileElement o = xml.obstacles.all.get(i);
            String name;
            ObstacleShape shape;
            Boolean tag;
            String colour;
            if (o instanceof EnvironmentFile.RectangleXml r) {
                name = nameOr(r.name, i);
                shape = rectangle(faults, r, name);
                tag = r.taggable;
                colour = r.colour;
            } else {
                EnvironmentFile.PolygonXml p = (EnvironmentFile.PolygonXml) o;
                name = nameOr(p.name, i);
                shape = polygon(faults, p, name);
                tag = p.taggable;
                colour = p.colour;
            }
            if (colour != null) {
                faults.add(o.at, "obstacle \"" + FileFaults.cut(name) + "\" takes no colour (a region of the <floor> "
                        + "does)");
            }
            if (!names.add(name)) {
                faults.add(o.at, "obstacle name \"" + FileFaults.cut(name) + "\" is used twice");
            }
            if (shape != null) {
                out.add(shape);
                if (Boolean.TRUE.equals(tag)) {
                    taggable.add(name);
                }
            }
        }
        return new Obstacles(out, taggable, names);
    }

    private static ObstacleShape rectangle(FileFaults faults, EnvironmentFile.RectangleXml r, String name) {
        String el = "<rectangle name=\"" + FileFaults.cut(name) + "\">";
        Double x = required(faults, r, el, "x", r.x);
        Double y = required(faults, r, el, "y", r.y);
        Double w = required(faults, r, el, "width", r.width);
        Double h = required(faults, r, el, "height", r.height);
        if (w != null && h != null && (!(w > 0) || !(h > 0))) {
            faults.add(r.at, el + " width and height must be > 0 m, got " + w + " x " + h);
            return null;
        }
        return x == null || y == null || w == null || h == null ? null
                : ObstacleShape.rectangle(name, x * MM_PER_M, y * MM_PER_M, w * MM_PER_M, h * MM_PER_M);
    }

    private static ObstacleShape polygon(FileFaults faults, EnvironmentFile.PolygonXml p, String name) {
        String el = "<polygon name=\"" + FileFaults.cut(name) + "\">";
        double[] xy = points(faults, p, el);
        if (xy == null) {
            return null;
        }
        ObstacleShape shape = new ObstacleShape(name, xy);
        if (!robosim.environment.core.Obstacles.polygon(shape).isValid()) {
            faults.add(p.at, el + " points do not form a simple polygon (edges cross or repeat)");
            return null;
        }
        return shape;
    }

    private static String nameOr(String name, int index) {
        return name == null || name.isBlank() ? "obstacle" + (index + 1) : name;
    }

    /** The polygon's points, mm; null, its fault recorded, when they are not 3 or more pairs x,y of finite numbers. */
    static double[] points(FileFaults faults, EnvironmentFile.PolygonXml p, String el) {
        if (p.points == null || p.points.isBlank()) {
            faults.add(p.at, el + " needs points=\"x1,y1 x2,y2 x3,y3 ...\" (metres)");
            return null;
        }
        String[] pairs = p.points.trim().split("\\s+");
        if (pairs.length < 3) {
            faults.add(p.at, el + " needs at least 3 points, got " + pairs.length);
            return null;
        }
        double[] xy = new double[pairs.length * 2];
        for (int i = 0; i < pairs.length; i++) {
            String[] c = pairs[i].split(",");
            try {
                if (c.length != 2) {
                    throw new NumberFormatException();
                }
                xy[2 * i] = Double.parseDouble(c[0]) * MM_PER_M;
                xy[2 * i + 1] = Double.parseDouble(c[1]) * MM_PER_M;
                if (!Double.isFinite(xy[2 * i]) || !Double.isFinite(xy[2 * i + 1])) {
                    throw new NumberFormatException();
                }
            } catch (NumberFormatException e) {
                faults.add(p.at, el + " point '" + pairs[i] + "' is not of the form x,y (metres)");
                return null;
            }
        }
        return xy;
    }
}
