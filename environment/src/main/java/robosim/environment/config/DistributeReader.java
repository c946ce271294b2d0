package robosim.environment.config;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import robosim.environment.core.Placement;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.protocol.WorldObject;

/**
 * The {@code <distribute>} elements of an environment file, as ARGoS reads its own: {@code quantity} copies of one
 * template ({@code <robot>}, {@code <box>} or {@code <cylinder>}), named its name followed by a number from
 * {@code baseNum} ({@code fb} makes {@code fb0}, {@code fb1}, ...), each put where a {@code <position>} draw and an
 * {@code <orientation>} draw say, drawn again (up to {@code maxTrials} times) while it would overlap the arena's edge
 * or what was placed before it. One generator, seeded by the world's seed and the element's number, draws everything
 * an element places, so a file and a seed give one world.
 *
 * <p>Positions, metres: {@code uniform} (each coordinate from {@code min} up to {@code max}), {@code gaussian}
 * ({@code mean}, {@code stdDev}), {@code constant} ({@code values}) and {@code grid} ({@code center}, {@code distances}
 * between neighbours, {@code layout} columns and rows; each try takes the next point, row by row from the lower left,
 * and running out of points ends it). Headings, degrees: {@code uniform} ({@code min}, {@code max}), {@code gaussian},
 * {@code constant}; without {@code <orientation>}, 0. A point or a heading may have a third (ARGoS's z) or Euler
 * angles after the first: a flat world ignores them.
 */
final class DistributeReader {
    private static final double MM_PER_M = 1000.0;
    /** Tries an entity takes without {@code maxTrials}. */
    static final int DEFAULT_TRIES = 100;
    /** The most tries one entity may be given. */
    static final int MAX_TRIES = 100_000;
    /** Mixes the world's seed with an element's number (the golden ratio's bits, as SplittableRandom's own). */
    private static final long MIX = 0x9E3779B97F4A7C15L;

    private DistributeReader() {
    }

    /** What the file's {@code <distribute>}s placed: robots there from the start and objects. */
    record Placed(List<RobotSpec> robots, List<WorldObject> objects) {
    }

    /**
     * Every {@code <distribute>}'s robots and objects, each checked against {@code placed} and added to it;
     * {@code robotNames} and {@code thingNames} (objects', obstacles') are the names taken. An element at fault
     * places nothing and records its faults; one whose entity finds no place records one fault, naming the entity,
     * and places no more (the file is refused either way).
     */
    static Placed read(FileFaults faults, EnvironmentFile xml, Placement placed, Set<String> robotNames,
            Set<String> thingNames, long seed) {
        Placed out = new Placed(new ArrayList<>(), new ArrayList<>());
        for (int d = 0; d < xml.distribute.size(); d++) {
            EnvironmentFile.DistributeXml e = xml.distribute.get(d);
            String el = "<distribute> number " + (d + 1);
            Draw position = draw(faults, e, el, "position", e.position, true);
            Draw heading = e.orientation == null ? new Constant(new double[] {0, 0})
                    : draw(faults, e, el, "orientation", e.orientation, false);
            Template template = template(faults, e, el);
            if (position == null || heading == null || template == null) {
                continue;
            }
            SplittableRandom random = new SplittableRandom(seed * MIX + d);
            List<String> names = new ArrayList<>();
            for (int i = 0; i < template.quantity; i++) {
                String name = template.base + (template.baseNum + i);
                Set<String> taken = template.robot != null ? robotNames : thingNames;
                if (taken.contains(name) || names.contains(name)) {
                    faults.add(e.entity.at, el + " would name an entity " + FileFaults.cut(name)
                            + ", a name already used");
                    break;
                }
                String why = null;
                boolean done = false;
                boolean gridFull = false;
                for (int t = 0; t < template.tries && !done; t++) {
                    double[] p = position.next(random);
                    if (p == null) {
                        gridFull = true;
                        break;
                    }
                    double x = p[0] * MM_PER_M;
                    double y = p[1] * MM_PER_M;
                    double h = robosim.geometry.Kinematics.turn(heading.next(random)[0], 0);
                    if (template.robot != null) {
                        RobotSpec r = template.robot;
                        why = placed.overlapOfDisc(x, y, r.radiusMm());
                        if (why == null) {
                            RobotSpec made = new RobotSpec(name, r.type(), r.control(), x, y, h, r.sensors(),
                                    r.sonarNoiseMm(), r.radiusMm(), r.sonarCount(), r.actuators());
                            placed.addRobot(name, x, y, r.radiusMm());
                            out.robots().add(made);
                            done = true;
                        }
                    } else {
                        WorldObject o = template.object;
                        WorldObject made = new WorldObject(name, o.shape(), o.widthMm(), o.depthMm(), o.heightMm(),
                                o.massKg(), o.friction(), o.movable(), o.gripable(), o.rgb(), x, y, h);
                        why = placed.overlapOf(made);
                        if (why == null) {
                            placed.addObject(made);
                            out.objects().add(made);
                            done = true;
                        }
                    }
                }
                if (!done) {
                    faults.add(e.entity.at, el + " could not place " + FileFaults.cut(name) + " (entity " + (i + 1)
                            + " of " + template.quantity + ")" + (gridFull ? ": its grid has no point left"
                            + (why == null ? "" : " (the last overlapped " + why + ")")
                            : " in " + template.tries + " tries: the last overlapped " + why));
                    break;
                }
                names.add(name);
            }
            (template.robot != null ? robotNames : thingNames).addAll(names);
        }
        return out;
    }

    /** An element's template: how many, its tries, its name's base and number, and the robot or object it makes. */
    private record Template(int quantity, int tries, int baseNum, String base, RobotSpec robot, WorldObject object) {
    }

    private static Template template(FileFaults faults, EnvironmentFile.DistributeXml e, String el) {
        EnvironmentFile.EntityXml entity = e.entity;
        if (entity == null) {
            faults.add(e.at, el + " needs an <entity quantity=\"..\"> holding one <robot>, <box> or <cylinder>");
            return null;
        }
        int held = (entity.robot == null ? 0 : 1) + (entity.box == null ? 0 : 1) + (entity.cylinder == null ? 0 : 1);
        boolean bad = false;
        if (held != 1) {
            faults.add(entity.at, el + " <entity> holds " + held + " templates; it needs exactly one <robot>, <box> or "
                    + "<cylinder>");
            bad = true;
        }
        int most = entity.robot != null ? robosim.protocol.Limits.MAX_ROBOTS : robosim.protocol.Limits.MAX_OBJECTS;
        if (entity.quantity == null) {
            if (!entity.hadBadValue("quantity")) {
                faults.add(entity.at, el + " <entity> needs quantity (how many to place)");
            }
            bad = true;
        } else if (entity.quantity < 1 || entity.quantity > most) {
            faults.add(entity.at, el + " <entity> quantity must be in 1.." + most + ", got " + entity.quantity);
            bad = true;
        }
        int tries = entity.maxTrials == null ? DEFAULT_TRIES : entity.maxTrials;
        if (tries < 1 || tries > MAX_TRIES) {
            faults.add(entity.at, el + " <entity> maxTrials must be in 1.." + MAX_TRIES + ", got " + tries);
            bad = true;
        }
        int baseNum = entity.baseNum == null ? 0 : entity.baseNum;
        if (baseNum < 0) {
            faults.add(entity.at, el + " <entity> baseNum must be >= 0, got " + baseNum);
            bad = true;
        }
        if (bad) {
            return null;
        }
        if (entity.robot != null) {
            EnvironmentFile.RobotXml r = entity.robot;
            String name = r.name == null || r.name.isBlank() ? "robot" : r.name;
            String inner = el + " <robot name=\"" + FileFaults.cut(name) + "\">";
            if (r.x != null || r.y != null || r.heading != null || r.join != null || !r.params.isEmpty()) {
                faults.add(r.at, inner + " takes its place from <position> and <orientation> and its parameters from "
                        + "the world's <param>s: leave out x, y, heading, join and <param>");
                return null;
            }
            RobotSpec robot = RobotReader.robot(faults, r, inner, name, r.type, r.radius, r.sonars, r.sonarNoiseMm,
                    r.control, r.devices, r.sensors);
            return robot == null ? null : new Template(entity.quantity, tries, baseNum, name, robot, null);
        }
        EnvironmentFile.ObjectXml o = entity.box != null ? entity.box : entity.cylinder;
        String name = o.name == null || o.name.isBlank() ? (entity.box != null ? "box" : "cylinder") : o.name;
        String inner = el + " " + SceneryReader.element(o, name);
        if (o.x != null || o.y != null || o.heading != null) {
            faults.add(o.at, inner + " takes its place from <position> and <orientation>: leave out x, y and heading");
            return null;
        }
        WorldObject object = SceneryReader.object(faults, o, inner, name);
        return object == null ? null : new Template(entity.quantity, tries, baseNum, name, null, object);
    }

    /** Where the next try puts an entity (metres), or which way it faces (degrees, first); null: nothing left. */
    private interface Draw {
        double[] next(SplittableRandom random);
    }

    private record Uniform(double[] min, double[] max) implements Draw {
        @Override
        public double[] next(SplittableRandom random) {
            double[] out = new double[min.length];
            for (int k = 0; k < out.length; k++) {
                out[k] = min[k] + (max[k] - min[k]) * random.nextDouble();
            }
            return out;
        }
    }

    private record Gaussian(double[] mean, double[] stdDev) implements Draw {
        @Override
        public double[] next(SplittableRandom random) {
            double[] out = new double[mean.length];
            for (int k = 0; k < out.length; k++) {
                out[k] = mean[k] + stdDev[k] * gaussian(random);
            }
            return out;
        }

        /** A standard normal number (Marsaglia's polar method: SplittableRandom has none of its own in Java 17). */
        private static double gaussian(SplittableRandom random) {
            while (true) {
                double u = 2 * random.nextDouble() - 1;
                double v = 2 * random.nextDouble() - 1;
                double s = u * u + v * v;
                if (s > 0 && s < 1) {
                    return u * Math.sqrt(-2 * Math.log(s) / s);
                }
            }
        }
    }

    private record Constant(double[] values) implements Draw {
        @Override
        public double[] next(SplittableRandom random) {
            return values.clone();
        }
    }

    /** The points of a grid in turn, row by row from the lower left. */
    private static final class Grid implements Draw {
        private final double x0;
        private final double y0;
        private final double dx;
        private final double dy;
        private final int columns;
        private final long points;
        private long taken;

        Grid(double[] center, double[] distances, int columns, int rows) {
            this.dx = distances[0];
            this.dy = distances[1];
            this.x0 = center[0] - dx * (columns - 1) / 2;
            this.y0 = center[1] - dy * (rows - 1) / 2;
            this.columns = columns;
            this.points = (long) columns * rows;
        }

        @Override
        public double[] next(SplittableRandom random) {
            if (taken == points) {
                return null;
            }
            long k = taken++;
            return new double[] {x0 + dx * (k % columns), y0 + dy * (k / columns)};
        }
    }

    /**
     * A {@code <position>} ({@code point} true: two numbers, or three) or an {@code <orientation>} (one number, or
     * three), read; null, its fault recorded, when at fault.
     */
    private static Draw draw(FileFaults faults, EnvironmentFile.DistributeXml e, String el, String what,
            EnvironmentFile.MethodXml m, boolean point) {
        String inner = el + " <" + what + ">";
        if (m == null) {
            faults.add(e.at, el + " needs a <" + what + " method=\"..\">");
            return null;
        }
        String method = m.method == null ? "" : m.method;
        int size = point ? 2 : 1;
        try {
            switch (method) {
                case "uniform" -> {
                    double[] min = numbers(inner, "min", m.min, size);
                    double[] max = numbers(inner, "max", m.max, size);
                    for (int k = 0; k < size; k++) {
                        if (!(min[k] <= max[k])) {
                            throw new IllegalArgumentException(inner + " min must not be above max, got min=\"" + m.min
                                    + "\" max=\"" + m.max + "\"");
                        }
                    }
                    return new Uniform(min, max);
                }
                case "gaussian" -> {
                    double[] std = numbers(inner, "stdDev", m.stdDev, size);
                    for (double s : std) {
                        if (!(s >= 0)) {
                            throw new IllegalArgumentException(inner + " stdDev must be >= 0, got \"" + m.stdDev + "\"");
                        }
                    }
                    return new Gaussian(numbers(inner, "mean", m.mean, size), std);
                }
                case "constant" -> {
                    return new Constant(numbers(inner, "values", m.values, size));
                }
                case "grid" -> {
                    if (!point) {
                        throw new IllegalArgumentException(inner + " method \"grid\" places positions only: use "
                                + "uniform, gaussian or constant");
                    }
                    double[] layout = numbers(inner, "layout", m.layout, 2);
                    for (double n : layout) {
                        if (n != Math.rint(n) || n < 1 || n > 1_000_000) {
                            throw new IllegalArgumentException(inner + " layout must be whole numbers of columns and "
                                    + "rows, 1 or more, got \"" + m.layout + "\"");
                        }
                    }
                    return new Grid(numbers(inner, "center", m.center, 2), numbers(inner, "distances", m.distances, 2),
                            (int) layout[0], (int) layout[1]);
                }
                default -> throw new IllegalArgumentException(inner + " method must be uniform, gaussian, constant"
                        + (point ? " or grid" : "") + ", got \"" + FileFaults.cut(method) + "\"");
            }
        } catch (IllegalArgumentException bad) {
            faults.add(m.at, bad.getMessage());
            return null;
        }
    }

    /** {@code size} finite numbers, comma-separated, or three of which the first {@code size} are kept. */
    private static double[] numbers(String el, String attribute, String text, int size) {
        if (text == null) {
            throw new IllegalArgumentException(el + " needs " + attribute);
        }
        String[] parts = text.trim().split("\\s*,\\s*");
        if (parts.length != size && parts.length != 3) {
            throw new IllegalArgumentException(el + " " + attribute + " must be " + (size == 2 ? "x,y" : "an angle")
                    + " (or three numbers, ARGoS's, the rest ignored), got \"" + FileFaults.cut(text) + "\"");
        }
        double[] out = new double[size];
        for (int k = 0; k < size; k++) {
            try {
                out[k] = Double.parseDouble(parts[k]);
            } catch (NumberFormatException e) {
                out[k] = Double.NaN;
            }
            if (!Double.isFinite(out[k])) {
                throw new IllegalArgumentException(el + " " + attribute + " must be numbers, got \"" + FileFaults.cut(text)
                        + "\"");
            }
        }
        return out;
    }
}
