package robosim.environment.net;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import robosim.protocol.RobotHello;

/**
 * Robots leaving and coming back mid-run, as the {@link SimulationLoop} sees it: a robot whose connection
 * closes, fails or breaks the protocol is removed ({@code --on-robot-loss REMOVE}) or stays in the world
 * standing still for its return ({@code HOLD}, {@code WAIT}: {@link AwayRobots}); a process that says hello
 * with an away robot's name takes it over, at its current pose, at the next step. A change never happens
 * half-way through a step: while one is resolved or released it waits for the step's end, so the others'
 * poses do not depend on when a socket closed or a hello came. Loop thread only.
 */
abstract class RosterCycle extends RunLifecycle {
    final AwayRobots away;
    private final List<PendingDeparture> deferred = new ArrayList<>();
    private boolean toldEveryoneAway;

    RosterCycle(ClientWorkerCoordinator coordinator, RunListener listener) {
        super(coordinator, listener);
        this.away = new AwayRobots(robots.length, settings.onRobotLoss());
    }

    /** Robot i's connection has closed or failed. */
    void leave(int i, String why) {
        if (core == null || !core.present(i) || phase == Phase.ENDED) {
            return;
        }
        if (away.isJoining(i)) {
            away.clear(i); // it joined and went before it took part: lost like any robot
            activeCount++; // (never counted in; depart counts it out)
        } else if (away.isAway(i)) {
            away.notReturning(i); // the new connection went before it took over: away as before
            rosterChanged = true;
            return;
        } else if (away.isReturning(i)) {
            away.notReturning(i); // (a take-over said hello before the old loss took effect, and went too)
        }
        depart(i, why);
    }

    /**
     * Robot i no longer takes part: it is removed, or held for its return. While a step is being resolved
     * or released (its request is already in that step) this happens at the end of that step instead.
     */
    @Override
    void depart(int i, String why) {
        depart(i, why, false);
    }

    /** As {@link #depart(int, String)}; {@code forGood}: removed whatever {@code --on-robot-loss} says. */
    private void depart(int i, String why, boolean forGood) {
        if (phase == Phase.RESOLVING || phase == Phase.RELEASING) {
            if (!leaving[i]) {
                leaving[i] = true;
                deferred.add(new PendingDeparture(i, why, forGood));
                LOG.info("robot {} lost during step {} ({}); it stops taking part at the step's end",
                        name(i), phase == Phase.RELEASING ? step - 1 : step, Printable.of(why));
            } else if (forGood) {
                deferred.replaceAll(p -> p.robot() == i ? new PendingDeparture(i, p.why(), true) : p);
            }
            return;
        }
        if (away.isAway(i)) {
            if (forGood) {
                remove(i, Printable.of(why));
            }
            return;
        }
        activeCount--;
        rosterChanged = true;
        if (requests[i] != null) {
            requests[i] = null;
            arrived--;
        }
        String safe = Printable.of(why);
        String name = name(i);
        if (forGood || settings.onRobotLoss() == RobotLoss.REMOVE) {
            remove(i, safe);
            return;
        }
        away.leave(i, step, System.nanoTime());
        core.away(i, true);
        record.states = states(); // (before the log line: whoever reads it sees the state)
        LOG.warn("robot {} lost at step {} ({}); it stands where it is until a robot process says hello as {}{}",
                name, step, safe, name, settings.onRobotLoss() == RobotLoss.WAIT
                        ? ", and the world waits for it" + limit() : "");
        listener.robotHeld(name, step, safe);
    }

    private String limit() {
        return settings.stepTimeoutMs() > 0 ? " (at most " + settings.stepTimeoutMs() + " ms: the step timeout)" : "";
    }

    /** Takes robot i out of the world for good; {@code why} is safe to print. */
    private void remove(int i, String why) {
        away.clear(i);
        core.depart(i);
        rosterChanged = true;
        Departure d = new Departure(name(i), step, why);
        record.departures.add(d);
        record.states = states();
        LOG.warn("robot {} left at step {} ({}); it is removed from the world and the others go on", d.robot(), step,
                why);
        listener.robotLeft(d);
    }

    /** The departures held back during the step just released take effect now. */
    @Override
    void departDeferred() {
        if (deferred.isEmpty()) {
            return;
        }
        List<PendingDeparture> due = List.copyOf(deferred);
        deferred.clear();
        for (PendingDeparture p : due) {
            leaving[p.robot()] = false;
            if (core.present(p.robot())) {
                depart(p.robot(), p.why(), p.forGood());
            }
        }
    }

    @Override
    void bringBackReturning() {
        for (int i = 0; i < robots.length; i++) {
            if (away.isReturning(i)) {
                bringBack(i);
            }
        }
    }

    @Override
    void grow(int n) {
        super.grow(n);
        away.grow(n);
    }

    @Override
    boolean away(int i) {
        return away.isAway(i);
    }

    private record PendingDeparture(int robot, String why, boolean forGood) {
    }

    /** The control port's {@code remove NAME}: null (removed now, or at the end of the step in progress) or why not. */
    String removeRobot(String name) {
        int i = indexOf(name);
        String shown = "\"" + Printable.of(name, 64) + "\"";
        if (i < 0) {
            return cancelAdded(name) ? null : "no robot named " + shown + " in this simulation";
        }
        if (core == null || phase == Phase.ENDED) {
            return "the simulation is " + (phase == Phase.ENDED ? "over" : "not running yet");
        }
        if (!core.present(i)) {
            return "robot " + shown + " has already left";
        }
        RobotPeer peer = robots[i];
        if (!peer.closed()) { // (not dropped: what it sends is ignored from now on, and it closes when told)
            peer.end(new robosim.protocol.SimulationEnd(step - 1, "removed from the simulation from the control port"),
                    peer.begun());
        }
        depart(i, "removed from the control port", true);
        return null;
    }

    /**
     * A hello naming robot i after the start: null (its welcome, with its current pose, is sent, and it
     * takes part from the next step) or the refusal.
     */
    String rejoin(RobotPeer worker, RobotHello hello, int i, Handshakes handshakes) {
        String name = name(i);
        if (phase == Phase.ENDED) {
            return "the simulation is over";
        }
        String noReturn = settings.onRobotLoss() == RobotLoss.REMOVE ? " (a lost robot may come back only when the "
                + "Environment runs with --on-robot-loss HOLD or WAIT)" : "";
        if (core == null || !core.present(i)) {
            return "robot " + name + " has been removed from the simulation" + noReturn;
        }
        if (!robots[i].closed()) {
            return "robot " + name + " is already connected (a new process takes over only once the old "
                    + "connection has closed)";
        }
        if (!away.isAway(i) && !leaving[i]) {
            depart(i, "its connection closed"); // before the loop heard of it: it hears now
        }
        if (!noReturn.isEmpty()) {
            return "robot " + name + " has left the simulation" + noReturn;
        }
        if (away.isReturning(i)) {
            return "robot " + name + " is already coming back on another connection";
        }
        if (!hello.properties().equals(registered[i])) {
            return "robot " + name + " comes back with " + Handshakes.difference(hello.properties(), registered[i]);
        }
        try {
            worker.welcome(handshakes.welcome(core.map().spec().robots().get(i).at(core.map().xMm(i),
                    core.map().yMm(i), core.map().headingDeg(i)), names()));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        worker.assign(i);
        robots[i] = worker;
        away.returning(i);
        rosterChanged = true;
        record.states = states();
        LOG.info("robot {} says hello again: it takes part from the next step, at ({}, {}) mm heading {} deg", name,
                core.map().xMm(i), core.map().yMm(i), core.map().headingDeg(i));
        if (phase == Phase.COLLECTING && !leaving[i]) {
            bringBack(i); // the step being collected is its first
        }
        return null;
    }

    /** Robot i's new connection takes part from the step being collected: it gets that step's number. */
    void bringBack(int i) {
        String name = name(i);
        long since = away.sinceStep(i);
        boolean joined = away.isJoining(i);
        away.clear(i);
        core.away(i, false);
        activeCount++;
        toldEveryoneAway = false;
        rosterChanged = true;
        record.states = states();
        away.back(i, System.nanoTime()); // its step timeout runs from now, as the others' did from their step
        if (joined) {
            LOG.info("robot {} takes part from step {}", name, step);
        } else {
            LOG.info("robot {} is back at step {}, where it stood since step {}", name, step, since);
            listener.robotReturned(name, step);
        }
        try {
            robots[i].begin(step);
        } catch (IOException e) {
            robots[i].drop();
            depart(i, "could not send it step " + step + ": " + e.getMessage());
        }
    }

    /** True if {@code name} was added from the control port and had not joined: it is no longer let in. */
    abstract boolean cancelAdded(String name);

    /** Every robot in the world and its state now, in world order (for the control port). */
    List<RobotState> states() {
        java.util.Map<String, Long> gone = new java.util.HashMap<>();
        for (Departure d : record.departures) {
            gone.put(d.robot(), d.step());
        }
        List<RobotState> states = new ArrayList<>(robots.length);
        for (int i = 0; i < robots.length; i++) {
            String name = name(i);
            if (core == null) {
                states.add(new RobotState(name, robots[i] == null ? "expected" : "connected", -1));
            } else if (!core.present(i)) {
                states.add(new RobotState(name, "gone", gone.getOrDefault(name, -1L)));
            } else if (away.isAway(i)) {
                String state = away.isJoining(i) ? "joining" : away.isReturning(i) ? "returning"
                        : settings.onRobotLoss() == RobotLoss.WAIT ? "waiting" : "held";
                states.add(new RobotState(name, state, away.sinceStep(i)));
            } else {
                states.add(new RobotState(name, "running", -1));
            }
        }
        return List.copyOf(states);
    }

    /** True while the world waits because every robot in it is away. */
    boolean everyoneAway() {
        return toldEveryoneAway;
    }

    /** Every robot in the world is away: the world waits (said once) until one comes back or joins. */
    void waitForAnyone() {
        if (!toldEveryoneAway) {
            toldEveryoneAway = true;
            LOG.warn("every robot is away at step {}: the world waits until one comes back", step);
        }
    }

    /** Deadlines of robots the world waits for ({@code WAIT}): one away longer than the step timeout is removed. */
    void removeOverdue(long now) {
        for (int i = 0; i < robots.length; i++) {
            if (away.waitedTooLong(i, now, stepTimeoutNanos)) {
                remove(i, "did not come back within " + settings.stepTimeoutMs() + " ms (step timeout)");
            }
        }
    }
}
