package robosim.environment.net;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import robosim.environment.core.JoinRule;
import robosim.environment.core.SpawnPlacer;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Limits;
import robosim.protocol.RobotHello;
import robosim.protocol.WorldSnapshot;

/**
 * Robots joining a running world, as the {@link SimulationLoop} sees it: a hello whose name the file lets
 * in ({@code <robot join="any-time">}, or a {@code <join allow="...">} pattern) after the start is placed
 * (its start pose, or the first free pose of its spawn region: {@link SpawnPlacer}), added to the world
 * at once, standing still, and takes part from the next step (at once when the step being collected
 * waits for requests). Joins happen between steps only; the loop holds a hello that comes while a step is
 * resolved. Geometry gets the new world before the next step, viewers a new snapshot before the next
 * update, the recording a roster frame. Also the world a viewer that joins, or the recording, starts from.
 * Loop thread only.
 */
abstract class JoinCycle extends RosterCycle {
    /** Why no robot joins under {@code SEQUENTIAL}. */
    private static final String SEQUENTIAL_FIXED = "robots cannot join this run: its SEQUENTIAL coordinator reads a "
            + "fixed list of robots (THREADS or TWO_THREADS can)";

    /** Robots one run lets join, at most (each join grows every per-robot array and sends Geometry the world). */
    static final int MAX_JOINS = 10_000;
    /** Robots added from the control port and not joined yet, at most. */
    static final int MAX_ADDED = 64;

    /** The rule each robot joined by, in world order (null for the file's robots). */
    private final List<JoinRule> ruleOf = new ArrayList<>();
    private SpawnPlacer placer;
    /** The world has grown since viewers and the recording last had a snapshot. */
    private boolean grown;
    private int joins;

    /** Robots the control port added that have not joined yet, by name (read by robot workers' handshakes). */
    private final java.util.Map<String, JoinRule> added;

    JoinCycle(ClientWorkerCoordinator coordinator, RunListener listener) {
        super(coordinator, listener);
        this.added = coordinator.handshakes().added();
        for (int i = 0; i < robots.length; i++) {
            ruleOf.add(null);
        }
    }

    /**
     * The control port's {@code add}: null (a hello with the rule's name joins at its pose, once) or why not.
     * The name must be new (not in the world, not added already), the pose inside the arena and free now.
     */
    String add(JoinRule rule) {
        String name = rule.allow();
        if (settings.design() == CoordinatorDesign.SEQUENTIAL) {
            return SEQUENTIAL_FIXED;
        }
        if (phase == Phase.ENDED || phase == Phase.WAITING) {
            return "the simulation is " + (phase == Phase.ENDED ? "over" : "not running yet: add robots once it runs");
        }
        if (added.size() >= MAX_ADDED) {
            return MAX_ADDED + " added robots wait for their hello already (remove NAME cancels one)";
        }
        if (indexOf(name) >= 0 || added.containsKey(name)) {
            return "a robot named " + name + " is " + (added.containsKey(name) ? "added already" : "in the simulation");
        }
        WorldSpec.RobotSpec r = rule.template();
        robosim.protocol.Arena arena = spec.arena();
        if (r.xMm() - r.radiusMm() < arena.minXMm() || r.xMm() + r.radiusMm() > arena.maxXMm()
                || r.yMm() - r.radiusMm() < arena.minYMm() || r.yMm() + r.radiusMm() > arena.maxYMm()) {
            return "(" + r.xMm() / 1000 + ", " + r.yMm() / 1000 + ") m is not inside the arena for a " + r.type();
        }
        StringBuilder why = new StringBuilder();
        if (placer().place(rule, core.map(), why) == null) {
            return "(" + r.xMm() / 1000 + ", " + r.yMm() / 1000 + ") m is taken: " + why;
        }
        added.put(name, rule);
        LOG.info("robot {} added from the control port: a {} at ({}, {}) mm heading {} deg; it joins when it says hello",
                name, r.type(), r.xMm(), r.yMm(), r.headingDeg());
        return null;
    }

    @Override
    boolean cancelAdded(String name) {
        boolean was = added.remove(name) != null;
        if (was) {
            LOG.info("robot {}, added from the control port, is no longer let in (removed before it joined)", name);
        }
        return was;
    }

    private SpawnPlacer placer() {
        if (placer == null) {
            placer = new SpawnPlacer(spec);
        }
        return placer;
    }

    /** True while a step is being resolved: a hello waits until it is complete. */
    boolean midStep() {
        return phase == Phase.RESOLVING;
    }

    /** A hello after the start naming no robot of the world now: null (welcome sent, robot added) or the refusal. */
    String join(RobotPeer worker, RobotHello hello, Handshakes handshakes) {
        String name = hello.name();
        if (phase == Phase.ENDED) {
            return "the simulation is over";
        }
        JoinRule rule = handshakes.rule(name);
        if (settings.design() == CoordinatorDesign.SEQUENTIAL) {
            return SEQUENTIAL_FIXED;
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
        for (int i = 0; i < ruleOf.size(); i++) {
            members += ruleOf.get(i) == rule && core.present(i) ? 1 : 0;
        }
        if (members >= rule.max()) {
            return "the rule " + rule.allow() + " of " + spec.source() + " lets at most " + rule.max()
                    + " robot(s) take part at once";
        }
        if (robots.length >= Limits.MAX_ROBOTS) {
            return "the world holds " + robots.length + " robots, the most it may";
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
        List<String> names = names();
        names.add(name);
        try {
            worker.welcome(handshakes.welcome(robot, names));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        boolean byAdd = added.remove(name) != null; // (an added robot joins once; it may come back by name)
        handshakes.joined().put(name, rule);
        joins++;
        int i = core.add(robot, hello.properties());
        grow(i + 1);
        ruleOf.add(rule);
        worker.assign(i);
        robots[i] = worker;
        registered[i] = hello.properties();
        away.joining(i, step);
        core.arriving(i);
        grown = true;
        geometry.worldChanged(core.map().geometryWorld());
        rosterChanged = true;
        record.states = states();
        LOG.info("robot {} joins at ({}, {}) mm heading {} deg ({}): it takes part from the next step", name,
                at[0], at[1], robot.headingDeg(), byAdd ? "added from the control port" : (rule.spawn() == null
                        ? "any-time" : rule.allow()) + " of " + spec.source());
        listener.robotJoined(name, step);
        if (phase == Phase.COLLECTING) {
            bringBack(i); // the step being collected is its first
        }
        return null;
    }

    /** The world as it now stands, once, if robots have joined since the last call (else null). */
    WorldSnapshot takeRosterChange(long lastStep) {
        if (!grown) {
            return null;
        }
        grown = false;
        return core.map().snapshot(lastStep);
    }

    /** With {@code --record}: opens the recording at the start, from the world as a viewer would get it. */
    void startRecording() {
        if (settings.record() == null || recorder != null) {
            return;
        }
        try {
            recorder = new RunRecorder(settings.record(), snapshot());
        } catch (IOException e) {
            LOG.error("cannot record into {}: {}", settings.record(), e.toString());
        }
    }

    /** The world as a viewer that joins now starts from: the last step's poses, or the start poses. */
    WorldSnapshot snapshot() {
        return core != null ? core.map().snapshot(step - 1) : StartSnapshot.of(spec, registered);
    }
}
