package robosim.environment.core;

import java.util.regex.Pattern;

/**
 * Who may join a running world, from the file: one robot named {@code join="any-time"} (it enters at its
 * start pose), or any robot whose name matches a {@code <join allow="scout-*">} pattern (it enters at the
 * first free pose of the rule's spawn region). At most {@code max} of a rule's robots take part at once.
 *
 * @param allow the name, or a pattern in which {@code *} stands for any characters and {@code ?} for one
 * @param template what such a robot is: type, control, sensors, noise, radius; its pose is the start pose of
 *     an any-time robot, its heading the heading every robot of a spawn region starts with
 * @param spawn where robots of a pattern enter; null for an any-time robot
 */
public record JoinRule(String allow, WorldSpec.RobotSpec template, Spawn spawn, int max) {
    /** A spawn region, mm: its lower-left corner and size; robots enter at the first free pose, row by row. */
    public record Spawn(double xMm, double yMm, double widthMm, double heightMm) {
    }

    /** What the name of a robot that joins may be: 1 to 64 letters, digits and {@code - _ . :}. */
    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9_.:-]{1,64}");

    /** Null if a robot that joins may have this name, else why not (the name shown cleaned and cut). */
    public static String badName(String name) {
        if (name != null && NAME.matcher(name).matches()) {
            return null;
        }
        return "\"" + robosim.protocol.Printable.of(name, 64) + "\" is not a name a robot may join with (1 to 64 letters, digits and - _ . :)";
    }

    public JoinRule {
        if (max < 1) {
            throw new IllegalArgumentException("max must be >= 1, got " + max);
        }
    }

    /** True if a robot of this name may join by this rule. */
    public boolean matches(String name) {
        if (spawn == null) {
            return allow.equals(name);
        }
        StringBuilder regex = new StringBuilder();
        for (char c : allow.toCharArray()) {
            regex.append(c == '*' ? ".*" : c == '?' ? "." : Pattern.quote(String.valueOf(c)));
        }
        return Pattern.matches(regex.toString(), name);
    }

    /** The robot {@code name} joining by this rule, at the given pose (mm, degrees). */
    public WorldSpec.RobotSpec robot(String name, double xMm, double yMm) {
        WorldSpec.RobotSpec t = template;
        return new WorldSpec.RobotSpec(name, t.type(), t.control(), xMm, yMm, t.headingDeg(), t.sensors(),
                t.sonarNoiseMm(), t.radiusMm(), t.sonarCount(), t.actuators());
    }
}
