package robosim.environment.run;

import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import robosim.environment.core.JoinRule;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Printable;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotProperties;

/**
 * What a robot's hello is checked against before the loop sees it, on the thread that read it: the protocol
 * version, a name in the file or one a rule of the file or an {@code add} lets join, properties that do not
 * contradict it. The rules robots join by ({@code add}'s, and those robots have joined by) change on the loop
 * thread ({@link Admission}) and are read here by any thread.
 */
public final class HelloCheck {
    /** The refusal of a robot of any type whose rule went while its hello was checked ({@link #typed}). */
    static final String RULE_WENT = "the place it would take in the world went while its hello was checked (removed "
            + "from the control port?)";
    /** Names a refusal lists at most. */
    private static final int LISTED = 10;

    private final WorldSpec spec;
    private final List<String> names;
    /** Robots the control port has added that have not joined yet (the loop writes it). */
    private final Map<String, JoinRule> added = new ConcurrentHashMap<>();
    /** Robots that joined the running world, by name, with the rule they joined by (the loop writes it). */
    private final Map<String, JoinRule> joined = new ConcurrentHashMap<>();

    public HelloCheck(WorldSpec spec) {
        this.spec = spec;
        this.names = spec.robots().stream().map(WorldSpec.RobotSpec::name).toList();
    }

    /** The place in the file of the robot this hello names, or -1 (none, or one that joins by a rule). */
    private int indexOf(RobotHello hello) {
        return hello.name() == null ? -1 : spec.indexOf(hello.name());
    }

    /** Null if the hello may go to the loop, else the refusal; {@code index}: {@link #indexOf} the hello. */
    private String check(RobotHello hello, int index) {
        if (hello.protocolVersion() != Protocol.VERSION) {
            return "protocol version " + hello.protocolVersion() + " is not supported (the Environment speaks "
                    + Protocol.VERSION + ")";
        }
        if (hello.name() == null) {
            return "a robot must say its name";
        }
        if (spec.loopFunctions() != null && robosim.environment.core.LoopSpec.SENDER.equals(hello.name())) {
            return "\"" + robosim.environment.core.LoopSpec.SENDER + "\" is the name the world's loop functions' "
                    + "messages come from: no robot of it may have it";
        }
        WorldSpec.RobotSpec entry;
        if (index < 0) {
            JoinRule rule = rule(hello.name());
            if (rule != null && JoinRule.badName(hello.name()) != null) {
                return JoinRule.badName(hello.name());
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
            RobotProperties model = robosim.devices.RobotTypes.properties(entry.type());
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
    private RobotHello typed(RobotHello hello, int index) {
        if (!hello.anyType()) {
            return hello;
        }
        WorldSpec.RobotSpec entry = index >= 0 ? spec.robots().get(index) : entry(hello.name());
        RobotProperties model = entry == null ? null : robosim.devices.RobotTypes.properties(entry.type());
        return model == null ? null : new RobotHello(hello.name(), model);
    }

    /**
     * The whole check of a hello on the thread that read it: null and the hello as the loop takes it, or the
     * refusal.
     */
    public Checked admit(RobotHello hello) {
        int index = indexOf(hello);
        String refusal = check(hello, index);
        RobotHello typed = refusal == null ? typed(hello, index) : null;
        return new Checked(refusal == null && typed == null ? RULE_WENT : refusal, typed, index);
    }

    /** A hello checked: {@code refusal} null and the hello as the loop takes it, and its place in the file (or -1). */
    public record Checked(String refusal, RobotHello hello, int index) {
    }

    /** The entry of robot {@code name} that joins by a rule (or null when there is none by that name, any more). */
    private WorldSpec.RobotSpec entry(String name) {
        JoinRule rule = rule(name);
        return rule == null ? null : rule.robot(name, 0, 0);
    }

    /** The rule a robot of this name joins (or joined) by: an {@code add}, one it joined by, or the file's; or null. */
    JoinRule rule(String name) {
        JoinRule r = added.get(name);
        if (r == null) {
            r = joined.get(name);
        }
        return r != null ? r : spec.joinRule(name);
    }

    // ---- the loop thread changes the rules -------------------------------------------------------------------

    /** {@code add}: a robot of the rule's name may join, once. */
    void allow(JoinRule rule) {
        added.put(rule.allow(), rule);
    }

    /** A robot added and not joined yet is no longer let in (removed, or it has joined); its rule, or null. */
    JoinRule disallow(String name) {
        return added.remove(name);
    }

    /** Robot {@code name} joined by {@code rule}: it may come back by that name. */
    void joined(String name, JoinRule rule) {
        joined.put(name, rule);
    }

    /** True if robot {@code name} was added and has not joined yet. */
    boolean added(String name) {
        return added.containsKey(name);
    }

    /** Robots added and not joined yet. */
    int addedCount() {
        return added.size();
    }

    /** The names of the robots added and not joined yet, sorted. */
    List<String> addedNames() {
        return List.copyOf(new TreeSet<>(added.keySet()));
    }

    /** Names for a refusal: at most {@link #LISTED}, then how many in all (a refusal stays short in a large world). */
    private static String listed(List<String> all) {
        return all.size() <= LISTED ? String.join(", ", all)
                : String.join(", ", all.subList(0, LISTED)) + ", ... (" + all.size() + " in all)";
    }

    /** The file's join rules, for a refusal: "; may join: rover9, scout-*", or "" when there are none. */
    private String joiners() {
        if (spec.joins().isEmpty()) {
            return "";
        }
        return "; may join: " + listed(spec.joins().stream().map(JoinRule::allow).toList());
    }
}
