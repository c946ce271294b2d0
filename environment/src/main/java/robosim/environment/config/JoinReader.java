package robosim.environment.config;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import robosim.environment.core.JoinRule;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.protocol.Arena;

/**
 * The file's rules for robots that join a running world: each {@code <join allow="..."><spawn/></join>},
 * checked (a pattern, a robot type, a positive {@code max}, a spawn region inside the arena that holds at
 * least the robot), and each {@code <robot join="any-time">}, whose start pose the loader has checked.
 */
final class JoinReader {
    private static final double MM_PER_M = 1000.0;
    /** A rule's largest {@code max}: what one rule may let in at once. */
    static final int MAX_PER_RULE = robosim.protocol.Limits.MAX_ROBOTS;

    /** What a {@code <join allow>} pattern may hold: the characters of a joining robot's name, and * and ?. */
    private static final java.util.regex.Pattern PATTERN = java.util.regex.Pattern.compile("[A-Za-z0-9_.:*?-]{1,64}");

    private JoinReader() {
    }

    /** The rules: the any-time robots first (in file order), then the {@code <join>} elements. */
    static List<JoinRule> rules(String where, EnvironmentFile xml, Arena arena, List<RobotSpec> anyTime)
            throws EnvironmentFileException {
        List<JoinRule> out = new ArrayList<>();
        for (RobotSpec r : anyTime) {
            if (JoinRule.badName(r.name()) != null) {
                throw new EnvironmentFileException(where + ": <robot name=\"" + r.name() + "\" join=\"any-time\"> "
                        + "a robot that joins needs a name of 1 to 64 letters, digits and - _ . :");
            }
            out.add(new JoinRule(r.name(), r, null, 1));
        }
        Set<String> patterns = new HashSet<>();
        for (EnvironmentFile.JoinXml j : xml.joins) {
            if (j.allow == null || j.allow.isBlank()) {
                throw new EnvironmentFileException(where + ": <join> number " + (patterns.size() + 1)
                        + " needs allow=\"...\" (a name pattern such as scout-*)");
            }
            String el = "<join allow=\"" + j.allow + "\">";
            if (!PATTERN.matcher(j.allow).matches()) {
                throw new EnvironmentFileException(where + ": " + el + " a pattern is 1 to 64 letters, digits, - _ . : "
                        + "and the wildcards * and ?");
            }
            if (!patterns.add(j.allow)) {
                throw new EnvironmentFileException(where + ": " + el + " the pattern is used twice");
            }
            if (j.allow.equals(robosim.protocol.CommEvent.EVERYONE)) {
                throw new EnvironmentFileException(where + ": " + el + " \"*\" alone is reserved: it addresses every "
                        + "robot (write a prefix, e.g. scout-*)");
            }
            int max = j.max == null ? 0 : j.max;
            if (max < 1 || max > MAX_PER_RULE) {
                throw new EnvironmentFileException(where + ": " + el + " needs max=\"N\", from 1 to " + MAX_PER_RULE
                        + " (how many of its robots may take part at once), got " + j.max);
            }
            if (j.spawn == null) {
                throw new EnvironmentFileException(where + ": " + el + " needs a <spawn x=\"\" y=\"\" width=\"\" "
                        + "height=\"\"/> region (metres) where its robots enter");
            }
            double x = ObstacleReader.required(where, el + " <spawn>", "x", j.spawn.x) * MM_PER_M;
            double y = ObstacleReader.required(where, el + " <spawn>", "y", j.spawn.y) * MM_PER_M;
            double w = ObstacleReader.required(where, el + " <spawn>", "width", j.spawn.width) * MM_PER_M;
            double h = ObstacleReader.required(where, el + " <spawn>", "height", j.spawn.height) * MM_PER_M;
            double heading = j.heading == null ? 0 : j.heading;
            if (!Double.isFinite(heading)) {
                throw new EnvironmentFileException(where + ": " + el + " heading must be a finite number");
            }
            RobotSpec template = RobotReader.robot(where, el, j.allow, j.type, j.radius, j.sonars, j.sonarNoiseMm,
                    j.control, j.sensors, x + w / 2, y + h / 2, robosim.geometry.Kinematics.turn(heading, 0));
            double r = template.radiusMm();
            if (!(w >= 2 * r) || !(h >= 2 * r) || x < arena.minXMm() || y < arena.minYMm()
                    || x + w > arena.maxXMm() || y + h > arena.maxYMm()) {
                throw new EnvironmentFileException(where + ": " + el + " <spawn> must lie inside the arena and hold "
                        + "one robot (" + 2 * r / MM_PER_M + " m across), got " + j.spawn.x + ", " + j.spawn.y + ", "
                        + j.spawn.width + " x " + j.spawn.height + " m");
            }
            out.add(new JoinRule(j.allow, template, new JoinRule.Spawn(x, y, w, h), max));
        }
        return out;
    }
}
