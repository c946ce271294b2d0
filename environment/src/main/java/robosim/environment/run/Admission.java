package robosim.environment.run;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.JoinRule;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.SpawnPlacer;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Arena;
import robosim.protocol.Limits;
import robosim.protocol.Printable;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotWelcome;

/**
 * Who comes into the run, on the loop thread: the verdict on every robot's hello (a robot of the file before the
 * start; after it, one of the world that comes back on a new connection, or one that joins by a rule of the file
 * or an {@code add}), the welcome an accepted robot gets, and the control port's {@code add} and {@code remove}.
 * What a hello is checked against before it reaches the loop is the {@link HelloCheck}'s; what happens to a robot
 * once it is in is the {@link Roster}'s. Hellos that come while a step is resolved wait for its end: robots come
 * and go between steps only.
 */
final class Admission {
    private static final Logger LOG = LoggerFactory.getLogger(Admission.class);

    /** Robots one run lets join, at most (each join grows the world and sends Geometry the world). */
    static final int MAX_JOINS = 10_000;
    /** Robots added from the control port and not joined yet, at most. */
    static final int MAX_ADDED = 64;

    private final WorldSpec spec;
    private final Settings settings;
    private final HelloCheck check;
    private final Roster roster;
    private final Progress progress;
    private final GeometryLink geometry;
    private final RunListener listener;
    /** The file's robots' names, world order (what a robot of the file is welcomed with). */
    private final List<String> fileNames;
    /** Publishes the status; run before a log line about a robot, so whoever reads the line sees it. */
    private final Runnable publish;
    /** Hellos that came while a step was being resolved: answered once it is complete. */
    private final List<Hellos> held = new ArrayList<>();
    /** Changes of the robots added and not joined yet, so far: the status is published anew when it moves. */
    private long version;
    private int joins;
    private SpawnPlacer placer;
    private SimulationCore core;

    Admission(WorldSpec spec, Settings settings, HelloCheck check, Roster roster, Progress progress,
            GeometryLink geometry, RunListener listener, Runnable publish) {
        this.spec = spec;
        this.settings = settings;
        this.check = check;
        this.roster = roster;
        this.progress = progress;
        this.geometry = geometry;
        this.listener = listener;
        this.publish = publish;
        this.fileNames = spec.robots().stream().map(WorldSpec.RobotSpec::name).toList();
    }

    /** The run starts in {@code world}: from now on robots join it, or come back to it. */
    void start(SimulationCore world) {
        this.core = world;
    }

    /** Changes of the robots added and not joined yet, so far. */
    long version() {
        return version;
    }

    /** The names of the robots added and not joined yet, sorted. */
    List<String> added() {
        return check.addedNames();
    }

    // ---- hellos ----------------------------------------------------------------------------------------------

    /** Hellos that came together: answered now, or once the step being resolved is complete. */
    void hellos(Hellos h) {
        if (progress.phase() == Progress.Phase.RESOLVING) {
            held.add(h); // (a robot joins between steps: after this one is resolved)
            return;
        }
        for (Hellos.Hello j : h.hellos()) {
            String refusal = register(j);
            if (refusal != null) {
                j.peer().refused(refusal);
            }
            j.verdict().complete(refusal);
        }
        h.answered().answered(true);
    }

    /** Between steps: answers the next hellos held while a step was resolved; false if there were none. */
    boolean answerHeld() {
        if (held.isEmpty() || progress.phase() == Progress.Phase.RESOLVING) {
            return false;
        }
        hellos(held.remove(0));
        return true;
    }

    /** The run is over: the hellos still held are refused. */
    void refuseHeld() {
        held.forEach(Hellos::refuse);
        held.clear();
    }

    /** A robot's hello, already checked against the file: null (its welcome is sent) or the refusal. */
    private String register(Hellos.Hello j) {
        if (progress.phase() != Progress.Phase.WAITING) {
            int live = indexOf(j.hello().name());
            return live >= 0 ? rejoin(j.peer(), j.hello(), roster.get(live)) : join(j.peer(), j.hello());
        }
        if (j.index() < 0) {
            return "the simulation has not started: a robot that joins a running world says hello once it runs";
        }
        Roster.Slot s = roster.get(j.index());
        if (s.peer() != null) {
            return "robot " + s.name() + " is already connected";
        }
        try {
            j.peer().welcome(welcome(spec.robots().get(s.index()), fileNames));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        j.peer().assign(s.index());
        roster.connect(s, j.peer(), j.hello().properties());
        return null;
    }

    /**
     * A hello naming a robot of the world after the start: null (its welcome, with its current pose, is sent,
     * and it takes part from the next step) or the refusal.
     */
    private String rejoin(RobotPeer peer, RobotHello hello, Roster.Slot s) {
        if (progress.over()) {
            return Progress.OVER;
        }
        String noReturn = settings.onRobotLoss() == RobotLoss.REMOVE ? " (a lost robot may come back only when the "
                + "Environment runs with --on-robot-loss HOLD or WAIT)" : "";
        if (s.goneForGood()) {
            return "robot " + s.name() + " has been removed from the simulation" + noReturn;
        }
        if (!s.peer().closed()) {
            return "robot " + s.name() + " is already connected (a new process takes over only once the old "
                    + "connection has closed)";
        }
        if (s.running() && !s.leaving()) {
            roster.leave(s, "its connection closed", false); // before the loop heard of it: it hears now
        }
        if (!noReturn.isEmpty()) {
            return "robot " + s.name() + " has left the simulation" + noReturn;
        }
        if (s.comingBack()) {
            return "robot " + s.name() + " is already coming back on another connection";
        }
        if (!hello.properties().equals(s.properties())) {
            return "robot " + s.name() + " comes back with " + difference(hello.properties(), s.properties());
        }
        // (where it stands in the world it comes back to: a step held at the release point is computed already)
        double x = core.map().xMm(s.index());
        double y = core.map().yMm(s.index());
        double heading = core.map().headingDeg(s.index());
        try {
            peer.welcome(welcome(core.map().spec().robots().get(s.index()).at(x, y, heading), roster.names()));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        peer.assign(s.index());
        roster.takeOver(s, peer);
        LOG.info("robot {} says hello again: it takes part from the next step, at ({}, {}) mm heading {} deg",
                s.name(), mm(x), mm(y), deg(heading));
        if (progress.phase() == Progress.Phase.COLLECTING && !s.leaving()) {
            roster.bringBack(s); // the step being collected is its first
        }
        return null;
    }

    /** A hello after the start naming no robot of the world now: null (welcome sent, robot added) or the refusal. */
    private String join(RobotPeer peer, RobotHello hello) {
        String name = hello.name();
        if (progress.over()) {
            return Progress.OVER;
        }
        JoinRule rule = check.rule(name);
        String fixed = settings.design().refusesJoins();
        if (fixed != null) {
            return fixed;
        }
        if (rule == null) {
            return "no robot named \"" + Printable.of(name, 64) + "\" in " + spec.source() + " may join";
        }
        if (JoinRule.badName(name) != null) {
            return JoinRule.badName(name);
        }
        if (joins >= MAX_JOINS) {
            return "this run has let " + MAX_JOINS + " robots join, the most one run may";
        }
        long members = 0;
        for (Roster.Slot s : roster.all()) {
            members += s.rule() == rule && s.state() != Roster.Slot.State.GONE ? 1 : 0;
        }
        if (members >= rule.max()) {
            return "the rule " + rule.allow() + " of " + spec.source() + " lets at most " + rule.max()
                    + " robot(s) take part at once";
        }
        if (roster.size() >= Limits.MAX_ROBOTS) {
            return "the world holds " + roster.size() + " robots, the most it may";
        }
        StringBuilder why = new StringBuilder();
        double[] at = placer().place(rule, core.map(), why);
        if (at == null) {
            return rule.spawn() == null
                    ? "robot " + name + "'s start pose (" + rule.template().xMm() / 1000 + ", "
                            + rule.template().yMm() / 1000 + ") m in " + spec.source() + " is taken: " + why
                    : "the spawn region of " + rule.allow() + " in " + spec.source() + " has no free pose for "
                            + name + " (" + why + ")";
        }
        WorldSpec.RobotSpec robot = rule.robot(name, at[0], at[1]);
        List<String> names = roster.names();
        names.add(name);
        try {
            peer.welcome(welcome(robot, names));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        boolean byAdd = check.disallow(name) != null; // (an added robot joins once; it may come back by name)
        if (byAdd) {
            version++;
        }
        check.joined(name, rule);
        joins++;
        int i = core.add(robot, hello.properties());
        Roster.Slot s = roster.join(name, rule, peer, hello.properties());
        if (s.index() != i) {
            throw new IllegalStateException("robot " + name + " joined the core at " + i + " and the roster at "
                    + s.index());
        }
        peer.assign(i);
        core.arriving(i);
        geometry.worldChanged(core.map().geometryWorld());
        publish.run(); // (before the log line: whoever reads it sees the robot)
        LOG.info("robot {} joins at ({}, {}) mm heading {} deg ({}): it takes part from the next step", name,
                mm(at[0]), mm(at[1]), deg(robot.headingDeg()), byAdd ? "added from the control port"
                        : (rule.spawn() == null ? "any-time" : rule.allow()) + " of " + spec.source());
        listener.robotJoined(name, progress.step());
        if (progress.phase() == Progress.Phase.COLLECTING) {
            roster.bringBack(s); // the step being collected is its first
        }
        return null;
    }

    /**
     * The welcome of a robot at its pose (a start pose, or where it stands mid-run), with every robot's name, the
     * run's seed and its parameters.
     */
    private RobotWelcome welcome(WorldSpec.RobotSpec robot, List<String> robotNames) {
        return RobotWelcome.accepted(spec.timeStepMs(), robot.xMm(), robot.yMm(), robot.headingDeg(), robotNames,
                robot.sensorNames()).withStepMessages(settings.stepMessages())
                .withRun(spec.seed(), spec.parameters().of(robot.name())).withType(robot.type())
                .withActuators(robot.actuatorNames());
    }

    /** How the properties a returning robot says it has differ from those it had (the file's checks passed). */
    private static String difference(RobotProperties now, RobotProperties was) {
        if (now.maxSpeedMmPerS() != was.maxSpeedMmPerS()) {
            return "a top speed of " + now.maxSpeedMmPerS() + " mm/s where it had " + was.maxSpeedMmPerS();
        }
        if (now.maxTurnDegPerS() != was.maxTurnDegPerS()) {
            return "a top turn rate of " + now.maxTurnDegPerS() + " deg/s where it had " + was.maxTurnDegPerS();
        }
        return "other sonars or properties than it had";
    }

    // ---- the control port ------------------------------------------------------------------------------------

    /**
     * The control port's {@code add}: null (a hello with the rule's name joins at its pose, once) or why not.
     * The name must be new (not in the world, not added already), the pose inside the arena and free now.
     */
    String add(JoinRule rule) {
        String name = rule.allow();
        String fixed = settings.design().refusesJoins();
        if (fixed != null) {
            return fixed;
        }
        if (progress.over() || progress.phase() == Progress.Phase.WAITING) {
            return "the simulation is " + (progress.over() ? "over" : "not running yet: add robots once it runs");
        }
        if (check.addedCount() >= MAX_ADDED) {
            return MAX_ADDED + " added robots wait for their hello already (remove NAME cancels one)";
        }
        if (indexOf(name) >= 0 || check.added(name)) {
            return "a robot named " + name + " is " + (check.added(name) ? "added already" : "in the simulation");
        }
        WorldSpec.RobotSpec r = rule.template();
        Arena arena = spec.arena();
        if (r.xMm() - r.radiusMm() < arena.minXMm() || r.xMm() + r.radiusMm() > arena.maxXMm()
                || r.yMm() - r.radiusMm() < arena.minYMm() || r.yMm() + r.radiusMm() > arena.maxYMm()) {
            return "(" + r.xMm() / 1000 + ", " + r.yMm() / 1000 + ") m is not inside the arena for a " + r.type();
        }
        StringBuilder why = new StringBuilder();
        if (placer().place(rule, core.map(), why) == null) {
            return "(" + r.xMm() / 1000 + ", " + r.yMm() / 1000 + ") m is taken: " + why;
        }
        check.allow(rule);
        version++;
        LOG.info("robot {} added from the control port: {} at ({}, {}) mm heading {} deg; it joins when it says hello",
                name, withArticle(r.type()), mm(r.xMm()), mm(r.yMm()), deg(r.headingDeg()));
        return null;
    }

    /** The control port's {@code remove NAME}: null (removed now, or at the end of the step in progress) or why not. */
    String remove(String name) {
        int i = indexOf(name);
        String shown = "\"" + Printable.of(name, 64) + "\"";
        if (i < 0) {
            if (check.disallow(name) != null) {
                version++;
                LOG.info("robot {}, added from the control port, is no longer let in (removed before it joined)", name);
                return null;
            }
            return "no robot named " + shown + " in this simulation";
        }
        if (core == null || progress.over()) {
            return "the simulation is " + (progress.over() ? "over" : "not running yet");
        }
        Roster.Slot s = roster.get(i);
        if (s.state() == Roster.Slot.State.GONE) {
            return "robot " + shown + " has already left";
        }
        roster.remove(s);
        return null;
    }

    /** The index of the robot of this name in the world now, or -1. */
    private int indexOf(String robotName) {
        return core != null ? core.map().spec().indexOf(robotName) : spec.indexOf(robotName);
    }

    private SpawnPlacer placer() {
        if (placer == null) {
            placer = new SpawnPlacer(spec);
        }
        return placer;
    }

    /** A coordinate for a log line, to the millimetre. */
    private static long mm(double v) {
        return Math.round(v);
    }

    /** A heading for a log line, to a tenth of a degree. */
    private static double deg(double v) {
        return Math.round(v * 10) / 10.0;
    }

    /** "an ArRobot", "a Scout". */
    private static String withArticle(String type) {
        return ("AEIOUaeiou".indexOf(type.isEmpty() ? 'x' : type.charAt(0)) >= 0 ? "an " : "a ") + type;
    }
}
