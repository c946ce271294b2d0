package robosim.environment.config;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import robosim.protocol.ObstacleShape;

/**
 * The {@code <obstacles>} of an environment file (rectangles and simple polygons, metres to millimetres,
 * names unique) and the checked numbers every part of the file reads; each fault is one
 * {@link EnvironmentFileException} line naming the file, the element and what is wrong.
 */
final class ObstacleReader {
    private static final double MM_PER_M = 1000.0;

    private ObstacleReader() {
    }

    /** A number the element must have, finite. */
    static double required(String where, String element, String attribute, Double v)
            throws EnvironmentFileException {
        if (v == null) {
            throw new EnvironmentFileException(where + ": " + element + " needs the attribute " + attribute);
        }
        if (!Double.isFinite(v)) {
            throw new EnvironmentFileException(where + ": " + element + " " + attribute + " must be a finite number, got "
                    + v);
        }
        return v;
    }

    static List<ObstacleShape> obstacles(String where, EnvironmentFile xml) throws EnvironmentFileException {
        List<ObstacleShape> out = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (Object o : xml.obstacles.all) {
            ObstacleShape shape;
            if (o instanceof EnvironmentFile.RectangleXml r) {
                String el = "<rectangle name=\"" + nameOr(r.name, out.size()) + "\">";
                double x = required(where, el, "x", r.x);
                double y = required(where, el, "y", r.y);
                double w = required(where, el, "width", r.width);
                double h = required(where, el, "height", r.height);
                if (!(w > 0) || !(h > 0)) {
                    throw new EnvironmentFileException(where + ": " + el + " width and height must be > 0 m, got "
                            + w + " x " + h);
                }
                shape = ObstacleShape.rectangle(nameOr(r.name, out.size()), x * MM_PER_M, y * MM_PER_M, w * MM_PER_M,
                        h * MM_PER_M);
            } else {
                EnvironmentFile.PolygonXml p = (EnvironmentFile.PolygonXml) o;
                String el = "<polygon name=\"" + nameOr(p.name, out.size()) + "\">";
                shape = new ObstacleShape(nameOr(p.name, out.size()), points(where, el, p.points));
                if (!robosim.environment.core.Obstacles.polygon(shape).isValid()) {
                    throw new EnvironmentFileException(where + ": " + el + " points do not form a simple polygon"
                            + " (edges cross or repeat)");
                }
            }
            if (!names.add(shape.name())) {
                throw new EnvironmentFileException(where + ": obstacle name \"" + shape.name() + "\" is used twice");
            }
            out.add(shape);
        }
        return out;
    }

    private static String nameOr(String name, int index) {
        return name == null || name.isBlank() ? "obstacle" + (index + 1) : name;
    }

    private static double[] points(String where, String el, String text) throws EnvironmentFileException {
        if (text == null || text.isBlank()) {
            throw new EnvironmentFileException(where + ": " + el + " needs points=\"x1,y1 x2,y2 x3,y3 ...\" (metres)");
        }
        String[] pairs = text.trim().split("\\s+");
        if (pairs.length < 3) {
            throw new EnvironmentFileException(where + ": " + el + " needs at least 3 points, got " + pairs.length);
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
                throw new EnvironmentFileException(where + ": " + el + " point '" + pairs[i]
                        + "' is not of the form x,y (metres)");
            }
        }
        return xy;
    }
}
