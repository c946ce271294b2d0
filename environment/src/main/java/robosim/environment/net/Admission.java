package robosim.environment.net;

import robosim.protocol.Printable;
import java.util.List;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotModels;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotWelcome;

/**
 * What a robot's hello is checked against before the loop sees it (the protocol version, a name in the
 * file, or one a rule of the file or an {@code add} lets join; properties that do not contradict it) and the
 * welcome an accepted robot gets. Any thread.
 */
final class Admission {
    private final WorldSpec spec;
    private final List<String> names;
    private final boolean stepMessages;
    /** Robots the control port has added that have not joined yet (the loop writes it). */
    private final java.util.Map<String, robosim.environment.core.JoinRule> added =
            new java.util.concurrent.ConcurrentHashMap<>();
    /** Robots that joined the running world, by name, with the rule they joined by (the loop writes it). */
    private final java.util.Map<String, robosim.environment.core.JoinRule> joined =
            new java.util.concurrent.ConcurrentHashMap<>();

    Admission(WorldSpec spec, List<String> names, boolean stepMessages) {
        this.spec = spec;
        this.names = names;
        this.stepMessages = stepMessages;
    }

    /** The refusal of a robot of any type whose rule went while its hello was checked ({@link #typed}). */
    static final String RULE_WENT = "the place it would take in the world went while its hello was checked (removed from "
            + "the control port?)";

    /** Null if the hello may go to the loop, else the refusal. */
    String check(RobotHello hello, int index) {
        if (hello.protocolVersion() != Protocol.VERSION) {
            return "protocol version " + hello.protocolVersion() + " is not supported (the Environment speaks "
                    + Protocol.VERSION + ")";
        }
        if (hello.name() == null) {
            return "a robot must say its name";
        }
        WorldSpec.RobotSpec entry;
        if (index < 0) {
            robosim.environment.core.JoinRule rule = rule(hello.name());
            if (rule != null && robosim.environment.core.JoinRule.badName(hello.name()) != null) {
                return robosim.environment.core.JoinRule.badName(hello.name());
            }
            if (rule == null) {
                return "no robot named \"" + Printable.of(hello.name(), 64) + "\" in " + spec.source() + " (robots: "
                        + listed(names) + joiners() + ")";
            }
            entry = rule.robot(hello.name(), 0, 0);
        } else {
            entry = spec.robots().get(index);
        }
        if (hello.anyType()) {
            RobotProperties model = RobotModels.byName(entry.type());
            return model == null ? "robot " + entry.name() + " is a " + entry.type() + " in " + spec.source()
                    + ", a type a robot must name itself: give --type " + entry.type()
                    : entry.contradiction(model, spec.source());
        }
        return entry.contradiction(hello.properties(), spec.source());
    }

    /**
     * The hello as the loop takes it, once {@link #check} has passed it: a robot of any type has the properties of
     * the type the file gives it. Null if that is no longer one every process knows (the rule it joins by went, or
     * changed, since the check: {@code remove}, {@code add} from the control port meanwhile).
     */
    RobotHello typed(RobotHello hello, int index) {
        if (!hello.anyType()) {
            return hello;
        }
        WorldSpec.RobotSpec entry = entry(hello.name(), index);
        RobotProperties model = entry == null ? null : RobotModels.byName(entry.type());
        return model == null ? null : new RobotHello(hello.name(), model);
    }

    /**
     * The file's entry for robot {@code name} ({@code index} in the file, or -1 for one that joins by a rule), or null
     * when there is no rule by that name (any more).
     */
    private WorldSpec.RobotSpec entry(String name, int index) {
        if (index >= 0) {
            return spec.robots().get(index);
        }
        robosim.environment.core.JoinRule rule = rule(name);
        return rule == null ? null : rule.robot(name, 0, 0);
    }

    /** The rule a robot of this name joins (or joined) by: an {@code add}, one it joined by, or the file's; or null. */
    robosim.environment.core.JoinRule rule(String name) {
        robosim.environment.core.JoinRule r = added.get(name);
        if (r == null) {
            r = joined.get(name);
        }
        return r != null ? r : spec.joinRule(name);
    }

    /** Robots that joined the running world, by name, with their rules; the loop's to change. */
    java.util.Map<String, robosim.environment.core.JoinRule> joined() {
        return joined;
    }

    /** Robots added from the control port that have not joined yet, by name; the loop's to change. */
    java.util.Map<String, robosim.environment.core.JoinRule> added() {
        return added;
    }

    /** Names for a refusal: at most {@link #LISTED}, then how many in all (a refusal stays short in a large world). */
    private static String listed(List<String> all) {
        return all.size() <= LISTED ? String.join(", ", all)
                : String.join(", ", all.subList(0, LISTED)) + ", ... (" + all.size() + " in all)";
    }

    /** Names a refusal lists at most. */
    private static final int LISTED = 10;

    /** The file's join rules, for a refusal: "; may join: rover9, scout-*", or "" when there are none. */
    private String joiners() {
        if (spec.joins().isEmpty()) {
            return "";
        }
        return "; may join: " + listed(spec.joins().stream().map(robosim.environment.core.JoinRule::allow).toList());
    }

    /** How the properties a returning robot says it has differ from those it had (the file's checks passed). */
    static String difference(robosim.protocol.RobotProperties now, robosim.protocol.RobotProperties was) {
        if (now.maxSpeedMmPerS() != was.maxSpeedMmPerS()) {
            return "a top speed of " + now.maxSpeedMmPerS() + " mm/s where it had " + was.maxSpeedMmPerS();
        }
        if (now.maxTurnDegPerS() != was.maxTurnDegPerS()) {
            return "a top turn rate of " + now.maxTurnDegPerS() + " deg/s where it had " + was.maxTurnDegPerS();
        }
        return "other sonars or properties than it had";
    }

    /** The welcome of robot {@code index}: the time step, its start pose, every robot's name, its sensors. */
    RobotWelcome welcome(int index) {
        return welcome(spec.robots().get(index), names);
    }

    /**
     * The welcome of a robot at its pose (a start pose, or where it stands mid-run), with every robot's name, the
     * run's seed and its parameters.
     */
    RobotWelcome welcome(WorldSpec.RobotSpec robot, List<String> robotNames) {
        return RobotWelcome.accepted(spec.timeStepMs(), robot.xMm(), robot.yMm(), robot.headingDeg(), robotNames,
                robot.sensorNames()).withStepMessages(stepMessages)
                .withRun(spec.seed(), spec.parameters().of(robot.name())).withType(robot.type());
    }

}
