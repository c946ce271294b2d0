package robosim.environment.config;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.exc.InvalidFormatException;
import com.fasterxml.jackson.databind.exc.UnrecognizedPropertyException;
import com.fasterxml.jackson.dataformat.xml.XmlMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import robosim.environment.core.Parameters;
import robosim.environment.core.WorldSpec;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;

/**
 * Reads an environment file and checks it: metres become millimetres, every fault becomes one
 * {@link EnvironmentFileException} line that names the file, the element and what is wrong.
 */
public final class EnvironmentLoader {
    private static final double MM_PER_M = 1000.0;
    private static final XmlMapper MAPPER = XmlMapper.builder()
            .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES)
            .build();

    /** The largest environment file, bytes (a 1000-robot world is about 100 KB). */
    public static final int MAX_FILE_BYTES = 16 * 1024 * 1024;

    private final GeometryFactory jts = new GeometryFactory();
    /** {@code <robot join="any-time">}: not waited for at the start; it may join the running world. */
    static final String ANY_TIME = "any-time";

    /** Loads and checks {@code file}: a regular file of at most {@link #MAX_FILE_BYTES}; its placeholders' defaults. */
    public WorldSpec load(Path file) throws EnvironmentFileException {
        return load(file, Map.of());
    }

    /**
     * Loads and checks {@code file} with these parameters ({@code --param NAME=VALUE}): each replaces the file's
     * placeholder of that name ({@code ${NAME:default}}) and the value of the world's {@code <param name="NAME">};
     * a name that is neither is refused.
     */
    public WorldSpec load(Path file, Map<String, String> given) throws EnvironmentFileException {
        String where = file.toString();
        for (Map.Entry<String, String> g : given.entrySet()) {
            if (!Placeholders.NAME.matcher(g.getKey()).matches()
                    || robosim.protocol.Limits.utfLength(g.getValue()) > robosim.protocol.Limits.MAX_PARAMETER_BYTES) {
                throw new EnvironmentFileException(where + ": --param " + robosim.protocol.Printable.of(g.getKey(), 64)
                        + ": a name of 1 to 64 letters, digits, '_', '.' or '-' (not a digit first) and a value of at most "
                        + robosim.protocol.Limits.MAX_PARAMETER_BYTES + " bytes");
            }
        }
        EnvironmentFile xml;
        Placeholders.Replaced replaced;
        try {
            replaced = Placeholders.replace(where, new String(read(file, where), StandardCharsets.UTF_8), given);
            xml = MAPPER.readValue(replaced.text(), EnvironmentFile.class);
        } catch (NoSuchFileException e) {
            throw new EnvironmentFileException(where + ": file not found");
        } catch (UnrecognizedPropertyException e) {
            throw new EnvironmentFileException(where + at(e.getLocation()) + ": unknown element or attribute '"
                    + e.getPropertyName() + "' (known here: " + e.getKnownPropertyIds() + ")");
        } catch (InvalidFormatException e) {
            throw new EnvironmentFileException(where + at(e.getLocation()) + ": " + path(e) + " value '"
                    + e.getValue() + "' is not a " + e.getTargetType().getSimpleName().toLowerCase());
        } catch (JsonProcessingException e) {
            throw new EnvironmentFileException(where + at(e.getLocation()) + ": malformed XML: "
                    + e.getOriginalMessage().lines().findFirst().orElse(""));
        } catch (IOException e) {
            throw new EnvironmentFileException(where + ": cannot read: " + e.getMessage());
        }
        if (xml == null) {
            throw new EnvironmentFileException(where + ": empty file");
        }
        Parameters parameters = parameters(where, xml, replaced.names(), given);
        WorldSpec spec = check(where, xml);
        return new WorldSpec(spec.source(), spec.name(), spec.timeStepMs(), spec.seed(), spec.arena(), spec.obstacles(),
                spec.robots(), spec.commRangeMm(), spec.maxMessageBytes(), spec.heatSources(), spec.tagRangeMm(),
                spec.taggable(), spec.joins(), parameters);
    }

    /** The world's and each robot's {@code <param>}s, the given values over the world's; unknown given names refused. */
    private static Parameters parameters(String where, EnvironmentFile xml, java.util.Set<String> placeholders,
            Map<String, String> given) throws EnvironmentFileException {
        Map<String, String> world = params(where, "<environment>", xml.params);
        for (String name : given.keySet()) {
            if (!placeholders.contains(name) && !world.containsKey(name)) {
                java.util.TreeSet<String> known = new java.util.TreeSet<>(placeholders);
                known.addAll(world.keySet());
                throw new EnvironmentFileException(where + ": no parameter '" + robosim.protocol.Printable.of(name, 64)
                        + "' here (its parameters: " + (known.isEmpty() ? "none" : String.join(", ", known)) + ")");
            }
            if (world.containsKey(name)) {
                world.put(name, given.get(name));
            }
        }
        Map<String, Map<String, String>> robots = new java.util.LinkedHashMap<>();
        for (EnvironmentFile.RobotXml r : xml.robots) {
            if (!r.params.isEmpty()) {
                String el = "<robot name=\"" + r.name + "\">";
                Map<String, String> own = params(where, el, r.params);
                java.util.Set<String> all = new java.util.HashSet<>(world.keySet());
                all.addAll(own.keySet());
                if (all.size() > robosim.protocol.Limits.MAX_PARAMETERS) {
                    throw new EnvironmentFileException(where + ": " + el + " has " + all.size() + " parameters with the "
                            + "world's, at most " + robosim.protocol.Limits.MAX_PARAMETERS);
                }
                robots.put(r.name, own);
            }
        }
        return new Parameters(world, robots);
    }

    private static Map<String, String> params(String where, String el, List<EnvironmentFile.ParamXml> xml)
            throws EnvironmentFileException {
        Map<String, String> out = new java.util.LinkedHashMap<>();
        for (EnvironmentFile.ParamXml p : xml) {
            if (p.name == null || !Placeholders.NAME.matcher(p.name).matches()) {
                throw new EnvironmentFileException(where + ": " + el + " <param name=\"" + (p.name == null ? "" : p.name)
                        + "\"> needs a name of 1 to 64 letters, digits, '_', '.' or '-', not a digit first");
            }
            if (p.value == null) {
                throw new EnvironmentFileException(where + ": " + el + " <param name=\"" + p.name + "\"> needs a value");
            }
            if (robosim.protocol.Limits.utfLength(p.value) > robosim.protocol.Limits.MAX_PARAMETER_BYTES) {
                throw new EnvironmentFileException(where + ": " + el + " <param name=\"" + p.name + "\"> has a value "
                        + "longer than " + robosim.protocol.Limits.MAX_PARAMETER_BYTES + " bytes");
            }
            if (out.put(p.name, p.value) != null) {
                throw new EnvironmentFileException(where + ": " + el + " <param name=\"" + p.name
                        + "\"> is given twice");
            }
        }
        if (out.size() > robosim.protocol.Limits.MAX_PARAMETERS) {
            throw new EnvironmentFileException(where + ": " + el + " has " + out.size() + " <param>s, at most "
                    + robosim.protocol.Limits.MAX_PARAMETERS);
        }
        return out;
    }

    /** The bytes of a regular file no larger than the cap (a FIFO or a device is never opened). */
    private static byte[] read(Path file, String where) throws IOException, EnvironmentFileException {
        if (!Files.exists(file)) {
            throw new NoSuchFileException(where);
        }
        if (!Files.isRegularFile(file)) {
            throw new EnvironmentFileException(where + ": not a regular file");
        }
        byte[] bytes = new byte[0];
        if (Files.size(file) <= MAX_FILE_BYTES) {
            try (java.io.InputStream in = Files.newInputStream(file)) {
                bytes = in.readNBytes(MAX_FILE_BYTES + 1); // (bounded again: it may have grown)
            }
        }
        if (bytes.length > MAX_FILE_BYTES || Files.size(file) > MAX_FILE_BYTES) {
            throw new EnvironmentFileException(where + ": larger than the " + MAX_FILE_BYTES
                    + " bytes an environment file may have");
        }
        return bytes;
    }

    private static String at(JsonLocation location) {
        return location == null || location.getLineNr() < 0 ? ""
                : ":" + location.getLineNr() + ":" + location.getColumnNr();
    }

    private static String path(InvalidFormatException e) {
        StringBuilder b = new StringBuilder();
        for (var ref : e.getPath()) {
            if (ref.getFieldName() != null) {
                b.append(b.length() == 0 ? "" : "/").append(ref.getFieldName());
            }
        }
        return "<" + b + ">";
    }

    private WorldSpec check(String where, EnvironmentFile xml) throws EnvironmentFileException {
        String env = where + ": <environment>";
        if (xml.timeStepMs == null) {
            throw new EnvironmentFileException(env + " needs timeStepMs (the time step in milliseconds)");
        }
        if (xml.timeStepMs <= 0) {
            throw new EnvironmentFileException(env + " timeStepMs must be > 0, got " + xml.timeStepMs);
        }
        if (xml.arena == null) {
            throw new EnvironmentFileException(env + " needs an <arena width=\"..\" height=\"..\"/> (metres)");
        }
        EnvironmentFile.ArenaXml a = xml.arena;
        double ax = orZero(a.x);
        double ay = orZero(a.y);
        double w = ObstacleReader.required(where, "<arena>", "width", a.width);
        double h = ObstacleReader.required(where, "<arena>", "height", a.height);
        if (!(w > 0) || !(h > 0) || !Double.isFinite(ax) || !Double.isFinite(ay)) {
            throw new EnvironmentFileException(where + ": <arena> width and height must be > 0 m, got " + w + " x " + h);
        }
        Arena arena = new Arena(ax * MM_PER_M, ay * MM_PER_M, (ax + w) * MM_PER_M, (ay + h) * MM_PER_M);
        List<ObstacleShape> obstacles = ObstacleReader.obstacles(where, xml);
        java.util.Set<String> taggable = new java.util.HashSet<>();
        for (int o = 0; o < xml.obstacles.all.size(); o++) {
            Object x = xml.obstacles.all.get(o);
            Boolean t = x instanceof EnvironmentFile.RectangleXml r ? r.taggable : ((EnvironmentFile.PolygonXml) x).taggable;
            if (Boolean.TRUE.equals(t)) {
                taggable.add(obstacles.get(o).name());
            }
        }
        double tagRange = xml.tagRangeM == null ? WorldSpec.DEFAULT_TAG_RANGE_MM / MM_PER_M : xml.tagRangeM;
        if (!(tagRange > 0) || Double.isInfinite(tagRange)) {
            throw new EnvironmentFileException(env + " tagRangeM must be > 0 m, got " + tagRange);
        }
        List<RobotSpec> all = robots(where, xml, arena, obstacles);
        List<RobotSpec> robots = new ArrayList<>();
        List<RobotSpec> anyTime = new ArrayList<>();
        for (int i = 0; i < all.size(); i++) {
            (ANY_TIME.equals(xml.robots.get(i).join) ? anyTime : robots).add(all.get(i));
        }
        if (robots.isEmpty()) {
            throw new EnvironmentFileException(where + ": <robots> must name at least one <robot> there from the "
                    + "start (without join=\"any-time\")");
        }
        List<robosim.environment.core.JoinRule> joins = JoinReader.rules(where, xml, arena, anyTime);
        long seed = xml.seed == null ? 1L : xml.seed;
        String name = xml.name == null ? Path.of(where).getFileName().toString() : xml.name;
        double range = 0;
        if (xml.commRangeM != null) {
            if (!(xml.commRangeM > 0) || Double.isInfinite(xml.commRangeM)) {
                throw new EnvironmentFileException(env + " commRangeM must be > 0 m, got " + xml.commRangeM);
            }
            range = xml.commRangeM * MM_PER_M;
        }
        int maxBytes = xml.maxMessageBytes == null ? WorldSpec.DEFAULT_MAX_MESSAGE_BYTES : xml.maxMessageBytes;
        if (maxBytes < 1 || maxBytes > robosim.protocol.Limits.MAX_UTF_BYTES) {
            throw new EnvironmentFileException(env + " maxMessageBytes must be in 1.."
                    + robosim.protocol.Limits.MAX_UTF_BYTES + ", got " + maxBytes);
        }
        List<WorldSpec.HeatSource> heat = new ArrayList<>();
        for (EnvironmentFile.HeatXml src : xml.heatSources) {
            String el = "<heat name=\"" + (src.name == null ? "heat" + (heat.size() + 1) : src.name) + "\">";
            double hx = ObstacleReader.required(where, el, "x", src.x);
            double hy = ObstacleReader.required(where, el, "y", src.y);
            double intensity = ObstacleReader.required(where, el, "intensity", src.intensity);
            if (!(intensity >= 0)) {
                throw new EnvironmentFileException(where + ": " + el + " intensity must be >= 0, got " + intensity);
            }
            heat.add(new WorldSpec.HeatSource(src.name == null ? "heat" + (heat.size() + 1) : src.name, hx * MM_PER_M,
                    hy * MM_PER_M, intensity));
        }
        return new WorldSpec(where, name, xml.timeStepMs, seed, arena, obstacles, robots, range, maxBytes, heat,
                tagRange * MM_PER_M, taggable, joins);
    }

    private static double orZero(Double v) {
        return v == null ? 0 : v;
    }

    private List<RobotSpec> robots(String where, EnvironmentFile xml, Arena arena, List<ObstacleShape> obstacles)
            throws EnvironmentFileException {
        if (xml.robots.isEmpty()) {
            throw new EnvironmentFileException(where + ": <robots> must name at least one <robot>");
        }
        List<Geometry> walls = new ArrayList<>();
        for (ObstacleShape o : obstacles) {
            walls.add(robosim.environment.core.Obstacles.polygon(o));
        }
        List<RobotSpec> out = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (EnvironmentFile.RobotXml r : xml.robots) {
            if (r.name == null || r.name.isBlank()) {
                throw new EnvironmentFileException(where + ": <robot> number " + (out.size() + 1) + " needs a name");
            }
            String el = "<robot name=\"" + r.name + "\">";
            if (r.name.equals(robosim.protocol.CommEvent.EVERYONE)) {
                throw new EnvironmentFileException(where + ": " + el + " \"*\" is reserved: it addresses every robot");
            }
            if (!names.add(r.name)) {
                throw new EnvironmentFileException(where + ": " + el + " the name is used twice");
            }
            if (r.join != null && !r.join.equals(ANY_TIME)) {
                throw new EnvironmentFileException(where + ": " + el + " join must be \"" + ANY_TIME + "\" (or left "
                        + "out: there from the start), got \"" + r.join + "\"");
            }
            double x = ObstacleReader.required(where, el, "x", r.x) * MM_PER_M;
            double y = ObstacleReader.required(where, el, "y", r.y) * MM_PER_M;
            double heading = r.heading == null ? 0 : r.heading;
            if (!Double.isFinite(heading)) {
                throw new EnvironmentFileException(where + ": " + el + " heading must be a finite number");
            }
            RobotSpec robot = RobotReader.robot(where, el, r, x, y, robosim.geometry.Kinematics.turn(heading, 0));
            double rad = robot.radiusMm();
            if (x - rad < arena.minXMm() || x + rad > arena.maxXMm() || y - rad < arena.minYMm()
                    || y + rad > arena.maxYMm()) {
                throw new EnvironmentFileException(where + ": " + el + " at (" + r.x + ", " + r.y
                        + ") m does not fit inside the arena (radius " + rad / MM_PER_M + " m)");
            }
            Geometry body = jts.createPoint(new Coordinate(x, y));
            for (int o = 0; o < walls.size(); o++) {
                if (walls.get(o).distance(body) < rad) {
                    throw new EnvironmentFileException(where + ": " + el + " at (" + r.x + ", " + r.y
                            + ") m overlaps obstacle \"" + obstacles.get(o).name() + "\"");
                }
            }
            for (RobotSpec other : out) {
                double minimum = rad + other.radiusMm();
                if (Math.hypot(other.xMm() - x, other.yMm() - y) < minimum) {
                    throw new EnvironmentFileException(where + ": " + el + " overlaps robot \"" + other.name() + "\"");
                }
            }
            out.add(robot);
        }
        return out;
    }
}
