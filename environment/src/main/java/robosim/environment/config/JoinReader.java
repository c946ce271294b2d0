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
 * least the robot), and each {@code <robot join="any-time">}, which the loader has checked (its name, its start
 * pose). Each fault is recorded at its element.
 */
final class JoinReader {
    private static final double MM_PER_M = 1000.0;
    /** A rule's largest {@code max}: what one rule may let in at once. */
    static final int MAX_PER_RULE = robosim.protocol.Limits.MAX_ROBOTS;

    /** What a {@code <join allow>} pattern may hold: the characters of a joining robot's name, and * and ?. */
    private static final java.util.regex.Pattern PATTERN = java.util.regex.Pattern.compile("[A-Za-z0-9_.:*?-]{1,64}");

    private JoinReader() {
    }

    /**
     * The rules: the any-time robots first (in file order), then the {@code <join>} elements; those with a fault are
     * left out. {@code arena} is null when the file's is at fault (a spawn region is then not checked against it).
     */
    static List<JoinRule> rules(FileFaults faults, EnvironmentFile xml, Arena arena, List<RobotSpec> anyTime) {
        List<JoinRule> out = new ArrayList<>();
        for (RobotSpec r : anyTime) {
            out.add(new JoinRule(r.name(), r, null, 1));
        }
        Set<String> patterns = new HashSet<>();
        for (int i = 0; i < xml.joins.size(); i++) {
            EnvironmentFile.JoinXml j = xml.joins.get(i);
            boolean usable;
            String el;
            if (j.allow == null || j.allow.isBlank()) {
                el = "<join> number " + (i + 1);
                faults.add(j.at, el + " needs allow=\"...\" (a name pattern such as scout-*)");
                usable = false;
            } else {
                el = "<join allow=\"" + j.allow + "\">";
                usable = pattern(faults, j, el, patterns);
            }
            int max = j.max == null ? 0 : j.max;
            if ((max < 1 || max > MAX_PER_RULE) && !j.hadBadValue("max")) {
                faults.add(j.at, el + " needs max=\"N\", from 1 to " + MAX_PER_RULE + " (how many of its robots may "
                        + "take part at once), got " + j.max);
            }
            usable &= max >= 1 && max <= MAX_PER_RULE;
            double heading = j.heading == null ? 0 : j.heading;
            if (!Double.isFinite(heading)) {
                faults.add(j.at, el + " heading must be a finite number");
            }
            RobotSpec template = RobotReader.robot(faults, j, el, j.allow, j.type, j.radius, j.sonars, j.sonarNoiseMm,
                    j.control, j.devices, j.sensors);
            JoinRule.Spawn spawn = spawn(faults, j, el, arena, template);
            if (usable && template != null && spawn != null && Double.isFinite(heading)) {
                out.add(new JoinRule(j.allow, template.at(spawn.xMm() + spawn.widthMm() / 2,
                        spawn.yMm() + spawn.heightMm() / 2, robosim.geometry.Kinematics.turn(heading, 0)), spawn, max));
            }
        }
        return out;
    }

    /** Whether the rule's pattern is one, used once, and not {@code *} alone; each fault recorded. */
    private static boolean pattern(FileFaults faults, EnvironmentFile.JoinXml j, String el, Set<String> patterns) {
        if (!PATTERN.matcher(j.allow).matches()) {
            faults.add(j.at, el + " a pattern is 1 to 64 letters, digits, - _ . : and the wildcards * and ?");
            return false;
        }
        if (!patterns.add(j.allow)) {
            faults.add(j.at, el + " the pattern is used twice");
            return false;
        }
        if (j.allow.equals(robosim.protocol.CommEvent.EVERYONE)) {
            faults.add(j.at, el + " \"*\" alone is reserved: it addresses every robot (write a prefix, e.g. scout-*)");
            return false;
        }
        return true;
    }

    /**
     * The rule's spawn region, mm: inside the arena and holding one {@code template} (when neither is at fault);
     * null, its faults recorded, when it is missing or at fault.
     */
    private static JoinRule.Spawn spawn(FileFaults faults, EnvironmentFile.JoinXml j, String el, Arena arena,
            RobotSpec template) {
        EnvironmentFile.SpawnXml s = j.spawn;
        if (s == null) {
            faults.add(j.at, el + " needs a <spawn x=\"\" y=\"\" width=\"\" height=\"\"/> region (metres) where its "
                    + "robots enter");
            return null;
        }
        String label = el + " <spawn>";
        Double x = ObstacleReader.required(faults, s, label, "x", s.x);
        Double y = ObstacleReader.required(faults, s, label, "y", s.y);
        Double w = ObstacleReader.required(faults, s, label, "width", s.width);
        Double h = ObstacleReader.required(faults, s, label, "height", s.height);
        if (x == null || y == null || w == null || h == null || arena == null || template == null) {
            return null;
        }
        JoinRule.Spawn spawn = new JoinRule.Spawn(x * MM_PER_M, y * MM_PER_M, w * MM_PER_M, h * MM_PER_M);
        double r = template.radiusMm();
        if (!(spawn.widthMm() >= 2 * r) || !(spawn.heightMm() >= 2 * r) || spawn.xMm() < arena.minXMm()
                || spawn.yMm() < arena.minYMm() || spawn.xMm() + spawn.widthMm() > arena.maxXMm()
                || spawn.yMm() + spawn.heightMm() > arena.maxYMm()) {
            faults.add(s.at, label + " must lie inside the arena and hold one robot (" + 2 * r / MM_PER_M
                    + " m across), got " + s.x + ", " + s.y + ", " + s.width + " x " + s.height + " m");
            return null;
        }
        return spawn;
    }
}
