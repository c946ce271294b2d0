package robosim.environment.core;

import java.util.List;
import robosim.devices.DeviceSpec;
import robosim.devices.HeatSource;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;
import robosim.protocol.Scenery;

/**
 * An environment as loaded from its file, in world millimetres and degrees: immutable.
 *
 * @param source the file it came from, for messages
 * @param commRangeMm how far a COMMEVENT carries, centre to centre; 0 = everywhere
 * @param maxMessageBytes the largest payload a robot may send (modified UTF-8 bytes)
 * @param parameters what the file gives the control code ({@code <param>})
 * @param scenery its floor, lights and objects
 * @param loopFunctions the experiment's own code ({@code <loopFunctions>}), or null for none
 * @param redraw the same file's world drawn from another seed, where the file places things by chance
 *     ({@code <distribute>}); null where it does not
 */
public record WorldSpec(String source, String name, long timeStepMs, long seed, Arena arena,
        List<ObstacleShape> obstacles, List<RobotSpec> robots, double commRangeMm, int maxMessageBytes,
        List<HeatSource> heatSources, double tagRangeMm, java.util.Set<String> taggable, List<JoinRule> joins,
        Parameters parameters, Scenery scenery, LoopSpec loopFunctions, Redraw redraw) {
    /** A file's world drawn anew from a seed: its robots and objects placed as that seed's draws put them. */
    @FunctionalInterface
    public interface Redraw {
        /**
         * The world with {@code seed}, placed by its draws.
         *
         * @throws IllegalArgumentException in one line when that seed's draws cannot place an entity
         */
        WorldSpec at(long seed);
    }

    /** How far a tag reaches from the robot's rim by default, mm. */
    public static final double DEFAULT_TAG_RANGE_MM = 1000;
    /** A tag hits only what lies within this many degrees of the heading. */
    public static final double TAG_HALF_ANGLE_DEG = 30;

    /** Default payload limit: a few kilobytes, well under the wire's 65,535. */
    public static final int DEFAULT_MAX_MESSAGE_BYTES = 8192;

    public WorldSpec {
        if (timeStepMs <= 0) {
            throw new IllegalArgumentException("time step must be > 0 ms, got " + timeStepMs);
        }
        if (!(commRangeMm >= 0) || Double.isInfinite(commRangeMm)) {
            throw new IllegalArgumentException("communication range must be >= 0 mm, got " + commRangeMm);
        }
        if (maxMessageBytes < 1 || maxMessageBytes > robosim.protocol.Limits.MAX_UTF_BYTES) {
            throw new IllegalArgumentException("maxMessageBytes must be in 1.." + robosim.protocol.Limits.MAX_UTF_BYTES
                    + ", got " + maxMessageBytes);
        }
        obstacles = List.copyOf(obstacles);
        robots = List.copyOf(robots);
        heatSources = List.copyOf(heatSources);
        if (!(tagRangeMm > 0) || Double.isInfinite(tagRangeMm)) {
            throw new IllegalArgumentException("tag range must be > 0 mm, got " + tagRangeMm);
        }
        taggable = java.util.Set.copyOf(taggable);
        joins = List.copyOf(joins);
        java.util.Objects.requireNonNull(parameters, "parameters");
        java.util.Objects.requireNonNull(scenery, "scenery");
    }

    /** Without floor, lights and objects. */
    public WorldSpec(String source, String name, long timeStepMs, long seed, Arena arena,
            List<ObstacleShape> obstacles, List<RobotSpec> robots, double commRangeMm, int maxMessageBytes,
            List<HeatSource> heatSources, double tagRangeMm, java.util.Set<String> taggable, List<JoinRule> joins,
            Parameters parameters) {
        this(source, name, timeStepMs, seed, arena, obstacles, robots, commRangeMm, maxMessageBytes, heatSources,
                tagRangeMm, taggable, joins, parameters, Scenery.NONE, null, null);
    }

    /** Without parameters. */
    public WorldSpec(String source, String name, long timeStepMs, long seed, Arena arena,
            List<ObstacleShape> obstacles, List<RobotSpec> robots, double commRangeMm, int maxMessageBytes,
            List<HeatSource> heatSources, double tagRangeMm, java.util.Set<String> taggable, List<JoinRule> joins) {
        this(source, name, timeStepMs, seed, arena, obstacles, robots, commRangeMm, maxMessageBytes, heatSources,
                tagRangeMm, taggable, joins, Parameters.NONE);
    }

    /** Without join rules: only the file's robots, all there from the start. */
    public WorldSpec(String source, String name, long timeStepMs, long seed, Arena arena,
            List<ObstacleShape> obstacles, List<RobotSpec> robots, double commRangeMm, int maxMessageBytes,
            List<HeatSource> heatSources, double tagRangeMm, java.util.Set<String> taggable) {
        this(source, name, timeStepMs, seed, arena, obstacles, robots, commRangeMm, maxMessageBytes, heatSources,
                tagRangeMm, taggable, List.of());
    }

    /** This world with one more robot (one that joined the run). */
    public WorldSpec withRobot(RobotSpec robot) {
        List<RobotSpec> more = new java.util.ArrayList<>(robots);
        more.add(robot);
        return new WorldSpec(source, name, timeStepMs, seed, arena, obstacles, more, commRangeMm, maxMessageBytes,
                heatSources, tagRangeMm, taggable, joins, parameters, scenery, loopFunctions, null);
    }

    /** This world with {@code others} for its robots (the same robots elsewhere: a learning episode's start). */
    public WorldSpec withRobots(List<RobotSpec> others) {
        return new WorldSpec(source, name, timeStepMs, seed, arena, obstacles, others, commRangeMm, maxMessageBytes,
                heatSources, tagRangeMm, taggable, joins, parameters, scenery, loopFunctions, null);
    }

    /**
     * This world with another seed (a sweep's, {@code --seed}'s, an episode's): drawn anew where the file places
     * things by chance ({@link #redraw}), else the same world.
     *
     * @throws IllegalArgumentException in one line when that seed's draws cannot place an entity
     */
    public WorldSpec withSeed(long newSeed) {
        if (redraw != null) {
            return redraw.at(newSeed);
        }
        return new WorldSpec(source, name, timeStepMs, newSeed, arena, obstacles, robots, commRangeMm, maxMessageBytes,
                heatSources, tagRangeMm, taggable, joins, parameters, scenery, loopFunctions, null);
    }

    /** This world with other loop functions ({@code null}: none). */
    public WorldSpec withLoopFunctions(LoopSpec other) {
        return new WorldSpec(source, name, timeStepMs, seed, arena, obstacles, robots, commRangeMm, maxMessageBytes,
                heatSources, tagRangeMm, taggable, joins, parameters, scenery, other, redraw);
    }

    /** This world with other parameters for its control code (a test's, in code). */
    public WorldSpec withParameters(Parameters newParameters) {
        return new WorldSpec(source, name, timeStepMs, seed, arena, obstacles, robots, commRangeMm, maxMessageBytes,
                heatSources, tagRangeMm, taggable, joins, newParameters, scenery, loopFunctions, null);
    }

    /** Robots the join rules let take part at once, counted up to {@link #JOINABLE_CAP} (for connection and queue caps). */
    public int joinable() {
        return (int) Math.min(JOINABLE_CAP, joins.stream().mapToLong(JoinRule::max).sum());
    }

    /** The most {@link #joinable} counts: what the robot port and the loop's queue are sized for beyond the file. */
    public static final int JOINABLE_CAP = 2_000;

    /** The first join rule that lets a robot of this name in, or null. */
    public JoinRule joinRule(String robotName) {
        for (JoinRule j : joins) {
            if (j.matches(robotName)) {
                return j;
            }
        }
        return null;
    }

    /** With the default tag range and no taggable obstacles. */
    public WorldSpec(String source, String name, long timeStepMs, long seed, Arena arena,
            List<ObstacleShape> obstacles, List<RobotSpec> robots, double commRangeMm, int maxMessageBytes,
            List<HeatSource> heatSources) {
        this(source, name, timeStepMs, seed, arena, obstacles, robots, commRangeMm, maxMessageBytes, heatSources,
                DEFAULT_TAG_RANGE_MM, java.util.Set.of());
    }

    /** A world whose messages carry everywhere, with the default size limit, and no heat sources. */
    public WorldSpec(String source, String name, long timeStepMs, long seed, Arena arena,
            List<ObstacleShape> obstacles, List<RobotSpec> robots) {
        this(source, name, timeStepMs, seed, arena, obstacles, robots, 0, DEFAULT_MAX_MESSAGE_BYTES);
    }

    /** A world without heat sources. */
    public WorldSpec(String source, String name, long timeStepMs, long seed, Arena arena,
            List<ObstacleShape> obstacles, List<RobotSpec> robots, double commRangeMm, int maxMessageBytes) {
        this(source, name, timeStepMs, seed, arena, obstacles, robots, commRangeMm, maxMessageBytes, List.of());
    }

    /** Index of the robot with this name, or -1. */
    public int indexOf(String robotName) {
        for (int i = 0; i < robots.size(); i++) {
            if (robots.get(i).name().equals(robotName)) {
                return i;
            }
        }
        return -1;
    }

    /**
     * One robot named in the file.
     *
     * @param control the control class the headless runner starts for it (may be empty)
     * @param sensors its sensors, its type's (those the file leaves on, as it configures them) then the file's own
     *     ({@link Equipment})
     * @param sonarNoiseMm standard deviation of Gaussian noise on its sonar ranges
     * @param radiusMm the radius the robot must report: its model's, or the file's for a robot type class
     * @param sonarCount the number of sonars the robot must report, or -1 when the file does not say
     * @param actuators its actuators (its type's LEDs, range-and-bearing, ...)
     */
    public record RobotSpec(String name, String type, String control, double xMm, double yMm, double headingDeg,
            List<DeviceSpec> sensors, double sonarNoiseMm, double radiusMm, int sonarCount,
            List<DeviceSpec> actuators) {
        public RobotSpec {
            sensors = List.copyOf(sensors);
            actuators = List.copyOf(actuators);
        }

        /**
         * A robot of a registered type ({@code robosim.devices.RobotTypes}), its radius the type's, its devices the
         * type's with {@code sensors} added ({@link Equipment}).
         */
        public RobotSpec(String name, String type, String control, double xMm, double yMm, double headingDeg,
                List<DeviceSpec> sensors, double sonarNoiseMm) {
            this(name, type, control, xMm, yMm, headingDeg, Equipment.of(type, sensors, null), sonarNoiseMm,
                    robosim.devices.RobotTypes.properties(type).radiusMm(), -1);
        }

        private RobotSpec(String name, String type, String control, double xMm, double yMm, double headingDeg,
                Equipment equipment, double sonarNoiseMm, double radiusMm, int sonarCount) {
            this(name, type, control, xMm, yMm, headingDeg, equipment.sensors(), sonarNoiseMm, radiusMm, sonarCount,
                    equipment.actuators());
        }

        /** This robot standing at another pose (mm, degrees). */
        public RobotSpec at(double x, double y, double heading) {
            return new RobotSpec(name, type, control, x, y, heading, sensors, sonarNoiseMm, radiusMm, sonarCount,
                    actuators);
        }

        /** A robot of a known model with sonar only and no noise. */
        public RobotSpec(String name, String type, String control, double xMm, double yMm, double headingDeg) {
            this(name, type, control, xMm, yMm, headingDeg, List.of(), 0);
        }

        /**
         * Why the properties a robot reports contradict this entry, or null if they agree: its type,
         * radius and (when the file gives one) sonar count must be the file's.
         */
        public String contradiction(robosim.protocol.RobotProperties p, String source) {
            if (!type.equals(p.type())) {
                return "robot " + name + " is " + article(type) + " " + type + " in " + source + ", but says it is "
                        + article(p.type()) + " " + robosim.protocol.Printable.of(p.type(), 64) + " (robot.sh: give --type "
                        + type + ", or leave --type out to take the file's)";
            }
            if (Math.abs(p.radiusMm() - radiusMm) > 1e-6) {
                return "robot " + name + " has radius " + radiusMm / 1000 + " m in " + source + ", but says "
                        + p.radiusMm() / 1000 + " m";
            }
            if (sonarCount >= 0 && p.sonars().size() != sonarCount) {
                return "robot " + name + " has " + sonarCount + " sonars in " + source + ", but says "
                        + p.sonars().size();
            }
            return null;
        }

        /** "an" before a vowel ("an ArRobot"), else "a". */
        private static String article(String word) {
            return !word.isEmpty() && "AEIOUaeiou".indexOf(word.charAt(0)) >= 0 ? "an" : "a";
        }

        public List<String> sensorNames() {
            return sensors.stream().map(DeviceSpec::name).toList();
        }

        public List<String> actuatorNames() {
            return actuators.stream().map(DeviceSpec::name).toList();
        }
    }
}
