package robosim.environment.config;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectReader;
import com.fasterxml.jackson.dataformat.xml.XmlMapper;
import com.fasterxml.jackson.dataformat.xml.deser.FromXmlParser;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import robosim.environment.core.JoinRule;
import robosim.environment.core.LoopSpec;
import robosim.environment.core.Parameters;
import robosim.environment.core.Placement;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Arena;
import robosim.protocol.ControlScripts;
import robosim.protocol.Limits;
import robosim.protocol.ObstacleShape;
import robosim.protocol.Printable;
import robosim.protocol.Scenery;
import robosim.protocol.WorldObject;

/**
 * Reads an environment file and checks it: metres become millimetres. A file with faults is refused with one
 * {@link EnvironmentFileException} listing every fault found in one pass over it, each one line naming the file, the
 * line and column where the element at fault starts, the element and what is wrong ({@link FileFaults}: in file
 * order, at most {@link FileFaults#SHOWN}, then how many more). Two kinds of fault end the reading where they are,
 * after those found before them: XML that is not well-formed (the parser cannot go on) and faults of the
 * placeholders (the text to read is not known).
 */
public final class EnvironmentLoader {
    private static final double MM_PER_M = 1000.0;
    /** Binds a file; {@code xsi:nil} is an attribute like any other (no element of the file is ever null). */
    private static final ObjectReader READER = new XmlMapper(new PositionedXmlModule())
            .readerFor(EnvironmentFile.class)
            .with(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES, DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES)
            .without(FromXmlParser.Feature.PROCESS_XSI_NIL);

    /** The largest environment file, bytes (a 1000-robot world is about 100 KB). */
    public static final int MAX_FILE_BYTES = 16 * 1024 * 1024;

    /** {@code <robot join="any-time">}: not waited for at the start; it may join the running world. */
    static final String ANY_TIME = "any-time";

    /** The robots that could be placed: those there from the start and those that may join at any time. */
    private record Robots(List<RobotSpec> fromStart, List<RobotSpec> anyTime) {
    }

    /** Loads and checks {@code file}: a regular file of at most {@link #MAX_FILE_BYTES}; its placeholders' defaults. */
    public WorldSpec load(Path file) throws EnvironmentFileException {
        return load(file, Map.of());
    }

    /** The text of {@code file} (shown as {@code where}), read whole (at most {@link #MAX_FILE_BYTES}). */
    private static String text(Path file, String where) throws EnvironmentFileException {
        try {
            return new String(read(file, where), StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new EnvironmentFileException(where + ": file not found");
        } catch (IOException e) {
            throw new EnvironmentFileException(where + ": cannot read: " + e.getMessage());
        }
    }

    /**
     * The names {@code --param} may give {@code file}: its placeholders' ({@code ${NAME:default}}) and its world's
     * {@code <param>}s, sorted.
     *
     * @throws EnvironmentFileException the file cannot be read or is not an environment file
     */
    public java.util.SortedSet<String> parameterNames(Path file) throws EnvironmentFileException {
        String where = file.toString();
        String text = text(file, where);
        FileFaults faults = new FileFaults(where);
        Placeholders.Replaced replaced = Placeholders.replace(faults, text, Map.of());
        faults.throwIfAny();
        faults.placedBy(replaced.columns());
        EnvironmentFile xml = bind(faults, replaced.text());
        faults.throwIfAny();
        java.util.SortedSet<String> known = new TreeSet<>(replaced.names());
        xml.params.stream().filter(p -> p.name != null && Placeholders.NAME.matcher(p.name).matches())
                .forEach(p -> known.add(p.name));
        return known;
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
                    || Limits.utfLength(g.getValue()) > Limits.MAX_PARAMETER_BYTES) {
                throw new EnvironmentFileException(where + ": --param " + Printable.of(g.getKey(), 64)
                        + ": a name of 1 to 64 letters, digits, '_', '.' or '-' (not a digit first) and a value of at most "
                        + Limits.MAX_PARAMETER_BYTES + " bytes");
            }
        }
        String text = text(file, where);
        FileFaults faults = new FileFaults(where);
        Placeholders.Replaced replaced = Placeholders.replace(faults, text, given);
        faults.throwIfAny();
        faults.placedBy(replaced.columns()); // (from here on, places in the replaced text)
        EnvironmentFile xml = bind(faults, replaced.text());
        Path folder = file.toAbsolutePath().getParent();
        scriptsFrom(xml, folder);
        Parameters parameters = parameters(faults, xml, replaced.names(), given);
        WorldSpec.Redraw redraw = xml.distribute.isEmpty() ? null : new WorldSpec.Redraw() {
            @Override
            public WorldSpec at(long seed) { // (the file read and checked again, its draws from this seed)
                FileFaults again = new FileFaults(where);
                again.placedBy(replaced.columns());
                try {
                    return check(where, again, xml, parameters, folder, seed, this);
                } catch (EnvironmentFileException e) {
                    throw new IllegalArgumentException(e.getMessage() + " (with seed " + seed + ")", e);
                }
            }
        };
        long seed = xml.seed == null ? 1L : xml.seed;
        return check(where, faults, xml, parameters, folder, seed, redraw); // (throws every fault)
    }

    /**
     * Each robot's, distributed robot's and join rule's control script ({@code python:PATH}), and the loop functions'
     * script, made absolute: a relative path is the file's folder's.
     */
    private static void scriptsFrom(EnvironmentFile xml, Path folder) {
        for (EnvironmentFile.RobotXml r : xml.robots) {
            r.control = r.control == null ? null : ControlScripts.resolved(r.control, folder);
        }
        for (EnvironmentFile.JoinXml j : xml.joins) {
            j.control = j.control == null ? null : ControlScripts.resolved(j.control, folder);
        }
        for (EnvironmentFile.DistributeXml d : xml.distribute) {
            EnvironmentFile.RobotXml r = d.entity == null ? null : d.entity.robot;
            if (r != null && r.control != null) {
                r.control = ControlScripts.resolved(r.control, folder);
            }
        }
        if (xml.loopFunctions != null && xml.loopFunctions.className != null) {
            xml.loopFunctions.className = ControlScripts.resolved(xml.loopFunctions.className, folder);
        }
    }

    /**
     * The file's text bound to {@link EnvironmentFile}, each unknown element or attribute and each value not of its
     * type recorded on the way ({@link ProblemRecorder}); XML that is not well-formed, or no environment at all, ends
     * it, thrown with the faults found before.
     */
    private static EnvironmentFile bind(FileFaults faults, String text) throws EnvironmentFileException {
        EnvironmentFile xml;
        try {
            xml = READER.withHandler(new ProblemRecorder(faults)).readValue(text);
        } catch (JsonProcessingException e) {
            faults.add(FilePosition.of(e.getLocation()), "malformed XML: "
                    + e.getOriginalMessage().lines().findFirst().orElse(""));
            throw faults.exception();
        }
        if (xml == null) {
            faults.add(null, "empty file");
            throw faults.exception();
        }
        return xml;
    }

    /**
     * The world's and each robot's {@code <param>}s, the given values over the world's; a given name that is neither
     * a placeholder nor a world's {@code <param>} is a fault.
     */
    private static Parameters parameters(FileFaults faults, EnvironmentFile xml, Set<String> placeholders,
            Map<String, String> given) {
        Map<String, String> world = params(faults, xml, "<environment>", xml.params);
        Set<String> known = new TreeSet<>(placeholders);
        xml.params.stream().filter(p -> p.name != null && Placeholders.NAME.matcher(p.name).matches())
                .forEach(p -> known.add(p.name));
        for (Map.Entry<String, String> g : given.entrySet()) {
            if (!known.contains(g.getKey())) {
                faults.add(null, "no parameter '" + Printable.of(g.getKey(), 64) + "' here (its parameters: "
                        + (known.isEmpty() ? "none" : String.join(", ", known)) + ")");
            } else if (world.containsKey(g.getKey())) {
                world.put(g.getKey(), g.getValue());
            }
        }
        Map<String, Map<String, String>> robots = new LinkedHashMap<>();
        for (EnvironmentFile.RobotXml r : xml.robots) {
            if (!r.params.isEmpty()) {
                String el = "<robot name=\"" + FileFaults.cut(r.name) + "\">";
                Map<String, String> own = params(faults, r, el, r.params);
                Set<String> all = new HashSet<>(world.keySet());
                all.addAll(own.keySet());
                if (all.size() > Limits.MAX_PARAMETERS) {
                    faults.add(r.at, el + " has " + all.size() + " parameters with the world's, at most "
                            + Limits.MAX_PARAMETERS);
                }
                robots.put(r.name, own);
            }
        }
        return new Parameters(world, robots);
    }

    /**
     * The experiment's code ({@code <loopFunctions>}), or null for none: a Java class name (looked up when the run
     * starts, where control classes are) or a Python script ({@code python:PATH}, checked when the run starts), and
     * its {@code <param>}s.
     */
    private static LoopSpec loopFunctions(FileFaults faults, EnvironmentFile.LoopFunctionsXml xml) {
        if (xml == null) {
            return null;
        }
        String el = "<loopFunctions>";
        Map<String, String> params = params(faults, xml, el, xml.params);
        if (xml.className == null || !ControlScripts.isScript(xml.className)
                && !JAVA_CLASS.matcher(xml.className).matches()) {
            faults.add(xml.at, el + " needs class=\"...\", a Java class name (implementing robosim.loop.LoopFunctions) "
                    + "or python:FILE, got \"" + FileFaults.cut(xml.className) + "\"");
            return null;
        }
        return new LoopSpec(xml.className, params);
    }

    /** A Java class's binary name. */
    private static final java.util.regex.Pattern JAVA_CLASS = java.util.regex.Pattern.compile(
            "[\\p{javaJavaIdentifierStart}][\\p{javaJavaIdentifierPart}]*(\\.[\\p{javaJavaIdentifierStart}][\\p{javaJavaIdentifierPart}]*){0,50}");

    /** The {@code <param>}s of {@code owner} ({@code el} in a fault) that have no fault. */
    private static Map<String, String> params(FileFaults faults, FileElement owner, String el,
            List<EnvironmentFile.ParamXml> xml) {
        Map<String, String> out = new LinkedHashMap<>();
        for (EnvironmentFile.ParamXml p : xml) {
            if (p.name == null || !Placeholders.NAME.matcher(p.name).matches()) {
                faults.add(p.at, el + " <param name=\"" + FileFaults.cut(p.name) + "\"> needs a name of 1 to "
                        + "64 letters, digits, '_', '.' or '-', not a digit first");
            } else if (p.value == null) {
                faults.add(p.at, el + " <param name=\"" + FileFaults.cut(p.name) + "\"> needs a value");
            } else if (Limits.utfLength(p.value) > Limits.MAX_PARAMETER_BYTES) {
                faults.add(p.at, el + " <param name=\"" + FileFaults.cut(p.name) + "\"> has a value longer than "
                        + Limits.MAX_PARAMETER_BYTES + " bytes");
            } else if (out.put(p.name, p.value) != null) {
                faults.add(p.at, el + " <param name=\"" + FileFaults.cut(p.name) + "\"> is given twice");
            }
        }
        if (out.size() > Limits.MAX_PARAMETERS) {
            faults.add(owner.at, el + " has " + out.size() + " <param>s, at most " + Limits.MAX_PARAMETERS);
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

    /** The world the file describes; or, when a fault has been recorded (here or before), every fault thrown. */
    private WorldSpec check(String where, FileFaults faults, EnvironmentFile xml, Parameters parameters, Path folder,
            long seed, WorldSpec.Redraw redraw) throws EnvironmentFileException {
        String env = "<environment>";
        if (xml.timeStepMs == null) {
            if (!xml.hadBadValue("timeStepMs")) {
                faults.add(xml.at, env + " needs timeStepMs (the time step in milliseconds)");
            }
        } else if (xml.timeStepMs <= 0) {
            faults.add(xml.at, env + " timeStepMs must be > 0, got " + xml.timeStepMs);
        }
        Arena arena = arena(faults, xml);
        ObstacleReader.Obstacles obstacles = ObstacleReader.obstacles(faults, xml);
        double tagRange = xml.tagRangeM == null ? WorldSpec.DEFAULT_TAG_RANGE_MM / MM_PER_M : xml.tagRangeM;
        if (!(tagRange > 0) || Double.isInfinite(tagRange)) {
            faults.add(xml.at, env + " tagRangeM must be > 0 m, got " + tagRange);
        }
        Placement placed = new Placement(arena, obstacles.shapes());
        Set<String> thingNames = new HashSet<>(obstacles.names());
        List<WorldObject> objects = SceneryReader.objects(faults, xml, placed, thingNames);
        Robots robots = robots(faults, xml, placed);
        Set<String> robotNames = new HashSet<>();
        robots.fromStart().forEach(r -> robotNames.add(r.name()));
        robots.anyTime().forEach(r -> robotNames.add(r.name()));
        DistributeReader.Placed distributed = DistributeReader.read(faults, xml, placed, robotNames, thingNames, seed);
        objects.addAll(distributed.objects());
        robots.fromStart().addAll(distributed.robots());
        if (objects.size() > Limits.MAX_OBJECTS) {
            faults.add(xml.at, env + " places " + objects.size() + " objects in all, at most " + Limits.MAX_OBJECTS);
        }
        if (robots.fromStart().size() + robots.anyTime().size() > Limits.MAX_ROBOTS) {
            faults.add(xml.at, env + " places " + (robots.fromStart().size() + robots.anyTime().size())
                    + " robots in all, at most " + Limits.MAX_ROBOTS);
        }
        boolean distributes = xml.distribute.stream().anyMatch(d -> d.entity != null && d.entity.robot != null);
        if (xml.robots.isEmpty() && !distributes) {
            faults.add(xml.at, "<environment> needs at least one robot: a <robot> in <robots>, or a <distribute> of "
                    + "robots");
        } else if (!distributes && xml.robots.stream().allMatch(r -> ANY_TIME.equals(r.join))) {
            faults.add(xml.at, "<robots> must name at least one <robot> there from the start (without "
                    + "join=\"any-time\")");
        }
        List<JoinRule> joins = JoinReader.rules(faults, xml, arena, robots.anyTime());
        String name = xml.name == null ? Path.of(where).getFileName().toString() : xml.name;
        double range = 0;
        if (xml.commRangeM != null) {
            if (!(xml.commRangeM > 0) || Double.isInfinite(xml.commRangeM)) {
                faults.add(xml.at, env + " commRangeM must be > 0 m, got " + xml.commRangeM);
            }
            range = xml.commRangeM * MM_PER_M;
        }
        int maxBytes = xml.maxMessageBytes == null ? WorldSpec.DEFAULT_MAX_MESSAGE_BYTES : xml.maxMessageBytes;
        if (maxBytes < 1 || maxBytes > Limits.MAX_UTF_BYTES) {
            faults.add(xml.at, env + " maxMessageBytes must be in 1.." + Limits.MAX_UTF_BYTES + ", got " + maxBytes);
        }
        List<robosim.devices.HeatSource> heat = heatSources(faults, xml);
        Scenery scenery = new Scenery(SceneryReader.floor(faults, xml, folder), SceneryReader.lights(faults, xml),
                objects);
        LoopSpec loop = loopFunctions(faults, xml.loopFunctions);
        if (loop != null && java.util.stream.Stream.concat(robots.fromStart().stream(), robots.anyTime().stream())
                .anyMatch(r -> r.name().equals(LoopSpec.SENDER))) {
            faults.add(xml.loopFunctions.at, "<loopFunctions>: a robot is named \"" + LoopSpec.SENDER + "\", the name "
                    + "the loop functions' messages come from; rename it");
        }
        faults.throwIfAny();
        return new WorldSpec(where, name, xml.timeStepMs, seed, arena, obstacles.shapes(), robots.fromStart(), range,
                maxBytes, heat, tagRange * MM_PER_M, obstacles.taggable(), joins, parameters, scenery, loop, redraw);
    }

    /** The arena, mm; null, its fault recorded, when it is missing or at fault. */
    private static Arena arena(FileFaults faults, EnvironmentFile xml) {
        EnvironmentFile.ArenaXml a = xml.arena;
        if (a == null) {
            faults.add(xml.at, "<environment> needs an <arena width=\"..\" height=\"..\"/> (metres)");
            return null;
        }
        double ax = orZero(a.x);
        double ay = orZero(a.y);
        Double w = ObstacleReader.required(faults, a, "<arena>", "width", a.width);
        Double h = ObstacleReader.required(faults, a, "<arena>", "height", a.height);
        if (w == null || h == null) {
            return null;
        }
        if (!(w > 0) || !(h > 0) || !Double.isFinite(ax) || !Double.isFinite(ay)) {
            faults.add(a.at, "<arena> width and height must be > 0 m, got " + w + " x " + h);
            return null;
        }
        return new Arena(ax * MM_PER_M, ay * MM_PER_M, (ax + w) * MM_PER_M, (ay + h) * MM_PER_M);
    }

    private static double orZero(Double v) {
        return v == null ? 0 : v;
    }

    /** The heat sources that have no fault, mm. */
    private static List<robosim.devices.HeatSource> heatSources(FileFaults faults, EnvironmentFile xml) {
        List<robosim.devices.HeatSource> out = new ArrayList<>();
        for (int i = 0; i < xml.heatSources.size(); i++) {
            EnvironmentFile.HeatXml src = xml.heatSources.get(i);
            String name = src.name == null ? "heat" + (i + 1) : src.name;
            String el = "<heat name=\"" + FileFaults.cut(name) + "\">";
            Double x = ObstacleReader.required(faults, src, el, "x", src.x);
            Double y = ObstacleReader.required(faults, src, el, "y", src.y);
            Double intensity = ObstacleReader.required(faults, src, el, "intensity", src.intensity);
            if (intensity != null && !(intensity >= 0)) {
                faults.add(src.at, el + " intensity must be >= 0, got " + intensity);
            } else if (x != null && y != null && intensity != null) {
                out.add(new robosim.devices.HeatSource(name, x * MM_PER_M, y * MM_PER_M, intensity));
            }
        }
        return out;
    }

    /**
     * Every robot whose radius and pose could be read, each checked where it stands against what was placed before it
     * (inside the arena unless that is at fault, clear of the obstacles, the objects and the robots before it); the
     * others' faults recorded.
     */
    private Robots robots(FileFaults faults, EnvironmentFile xml, Placement placed) {
        Robots out = new Robots(new ArrayList<>(), new ArrayList<>());
        Set<String> names = new HashSet<>();
        for (int i = 0; i < xml.robots.size(); i++) {
            EnvironmentFile.RobotXml r = xml.robots.get(i);
            boolean named = r.name != null && !r.name.isBlank();
            String el = named ? "<robot name=\"" + FileFaults.cut(r.name) + "\">" : "<robot> number " + (i + 1);
            if (!named) {
                faults.add(r.at, el + " needs a name");
            } else if (r.name.equals(robosim.protocol.CommEvent.EVERYONE)) {
                faults.add(r.at, el + " \"*\" is reserved: it addresses every robot");
            } else if (!names.add(r.name)) {
                faults.add(r.at, el + " the name is used twice");
            }
            boolean anyTime = ANY_TIME.equals(r.join);
            if (r.join != null && !anyTime) {
                faults.add(r.at, el + " join must be \"" + ANY_TIME + "\" (or left out: there from the start), got \""
                        + r.join + "\"");
            }
            if (anyTime && named && JoinRule.badName(r.name) != null) {
                faults.add(r.at, "<robot name=\"" + FileFaults.cut(r.name) + "\" join=\"any-time\"> a robot that joins needs a name "
                        + "of 1 to 64 letters, digits and - _ . :");
            }
            Double x = ObstacleReader.required(faults, r, el, "x", r.x);
            Double y = ObstacleReader.required(faults, r, el, "y", r.y);
            double heading = r.heading == null ? 0 : r.heading;
            if (!Double.isFinite(heading)) {
                faults.add(r.at, el + " heading must be a finite number");
                heading = 0; // (the world is not built: it only keeps the robot's place checked)
            }
            RobotSpec robot = RobotReader.robot(faults, el, r);
            if (robot == null || x == null || y == null) {
                continue; // (where it stands cannot be checked)
            }
            robot = robot.at(x * MM_PER_M, y * MM_PER_M, robosim.geometry.Kinematics.turn(heading, 0));
            String over = placed.overlapOfDisc(robot.xMm(), robot.yMm(), robot.radiusMm());
            if (over != null) {
                faults.add(r.at, el + placeFault(over, r.x, r.y, robot.radiusMm()));
            }
            if (named) {
                placed.addRobot(robot.name(), robot.xMm(), robot.yMm(), robot.radiusMm());
            }
            (anyTime ? out.anyTime() : out.fromStart()).add(robot);
        }
        return out;
    }

    /** What a fault says after the element of a robot that does not fit where it stands ({@link Placement}). */
    static String placeFault(String over, Double x, Double y, double radiusMm) {
        if (over.equals("the arena's edge")) {
            return " at (" + x + ", " + y + ") m does not fit inside the arena (radius " + radiusMm / MM_PER_M + " m)";
        }
        return over.startsWith("robot") ? " overlaps " + over : " at (" + x + ", " + y + ") m overlaps " + over;
    }
}
