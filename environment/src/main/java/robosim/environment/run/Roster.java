package robosim.environment.run;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.LongSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.JoinRule;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Printable;
import robosim.protocol.RobotProperties;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepNumbers;
import robosim.protocol.StepRequest;

/**
 * The run's robots and their lifecycle: one {@link Slot} each, in world order (the file's robots, then those
 * that joined, in the order they did), each in one {@link Slot.State}, and every change of state, made here and
 * nowhere else: connected, started, lost (held, waited for, or removed, as {@code --on-robot-loss} says), taken
 * over by a new connection, brought back, joined, removed. It also collects the step's requests, and counts the
 * robots in each state as states change, so the loop's questions ("is everyone here?", "does the world wait?")
 * cost nothing per event. Robots come and go between steps only: one lost while a step is resolved or released
 * goes at that step's end ({@link #stepReleased}). Loop thread only.
 */
final class Roster {
    private static final Logger LOG = LoggerFactory.getLogger(Roster.class);

    /**
     * One robot of the run: its state, the connection that speaks for it, what it said it is, and what it asked.
     * Its place in the world's robot list ({@link #index}) never changes. Only the {@link Roster} changes it.
     */
    static final class Slot {
        /** Where a robot stands in the run; {@link #label} is the control port's word for it. */
        enum State {
            /** Named in the file, not connected yet (before the start). */
            EXPECTED("expected"),
            /** Connected, waiting for the start. */
            CONNECTED("connected"),
            /** Takes part in every step. */
            RUNNING("running"),
            /** Lost, standing in the world until a process says hello with its name ({@code HOLD}). */
            HELD("held"),
            /** Lost, and the world waits for it ({@code WAIT}), at most the step timeout. */
            WAITED("waiting"),
            /** A new connection takes it over at the next step. */
            RETURNING("returning"),
            /** Joined the running world; takes part from the next step. */
            JOINING("joining"),
            /** Out of the world for good. */
            GONE("gone");

            final String label;

            State(String label) {
                this.label = label;
            }

            /** In the world but not taking part: standing still where it is. */
            boolean away() {
                return this == HELD || this == WAITED || this == RETURNING || this == JOINING;
            }

            /**
             * The table of transitions:
             * <pre>
             * EXPECTED  -&gt; CONNECTED            its hello, before the start
             * CONNECTED -&gt; EXPECTED             its connection closed before the start
             *           -&gt; RUNNING              the run starts
             * RUNNING   -&gt; HELD | WAITED        lost, under --on-robot-loss HOLD | WAIT (at the step's end if mid-step)
             *           -&gt; RETURNING            lost while a new connection had already said hello with its name
             *           -&gt; GONE                 lost under REMOVE, or removed from the control port
             * HELD | WAITED -&gt; RETURNING        a new connection says hello with its name
             *           -&gt; GONE                 removed; WAITED: not back within the step timeout
             * RETURNING -&gt; RUNNING              the step being collected is its first again
             *           -&gt; HELD | WAITED        its new connection closed before it took part
             *           -&gt; GONE                 removed
             * JOINING   -&gt; RUNNING              the step being collected is its first; or lost before it took
             *                                  part: lost like any running robot
             *           -&gt; GONE                 removed
             * </pre>
             */
            boolean leadsTo(State to) {
                return switch (this) {
                    case EXPECTED -> to == CONNECTED;
                    case CONNECTED -> to == EXPECTED || to == RUNNING;
                    case RUNNING -> to == HELD || to == WAITED || to == RETURNING || to == GONE;
                    case HELD, WAITED -> to == RETURNING || to == GONE;
                    case RETURNING -> to == RUNNING || to == HELD || to == WAITED || to == GONE;
                    case JOINING -> to == RUNNING || to == GONE;
                    case GONE -> false;
                };
            }
        }

        /** A departure held back until the end of the step under way; {@code forGood}: removed whatever the policy. */
        private record Leaving(String why, boolean forGood) {
        }

        private final int index;
        private final String name;
        /** The rule it joined by; null for the file's robots. */
        private final JoinRule rule;
        private State state;
        /** Where the loop's messages to it go; null until it has said hello. */
        private RobotPeer peer;
        /** What it said it is in its hello; null until then. */
        private RobotProperties properties;
        /** Its request for the step being collected, or null. */
        private StepRequest request;
        /** What it asked in the step last released (its view, the recording), or null. */
        private StepRequest released;
        /** Away or gone: the first step it did not take part in. */
        private long sinceStep;
        /** Away: when it went (ns), for the step timeout of a robot the world waits for. */
        private long awayNanos;
        /** When it last came back (ns), 0 if never: its step timeout runs from then for the step it was given. */
        private long backNanos;
        /** Its departure, held back until the end of the step under way; or null. */
        private Leaving leaving;
        /** With {@link #leaving}: a new connection has said hello and takes over once it has left. */
        private boolean takeover;

        private Slot(int index, String name, JoinRule rule, State state) {
            this.index = index;
            this.name = name;
            this.rule = rule;
            this.state = state;
        }

        int index() {
            return index;
        }

        String name() {
            return name;
        }

        JoinRule rule() {
            return rule;
        }

        State state() {
            return state;
        }

        RobotPeer peer() {
            return peer;
        }

        RobotProperties properties() {
            return properties;
        }

        /** What it asked in the step last released, or null. */
        StepRequest released() {
            return released;
        }

        /** True while it takes part in the steps (also while it leaves at the end of this one). */
        boolean running() {
            return state == State.RUNNING;
        }

        /** True once it has left, or leaves at the end of the step under way, for good. */
        boolean goneForGood() {
            return state == State.GONE || leaving != null && leaving.forGood();
        }

        /** True while it leaves at the end of the step under way. */
        boolean leaving() {
            return leaving != null;
        }

        /** True while a new connection waits to take it over (at the next step, or once it has left). */
        boolean comingBack() {
            return state == State.RETURNING || state == State.JOINING || takeover;
        }
    }

    private final List<Slot> slots = new ArrayList<>();
    private final int[] counts = new int[Slot.State.values().length];
    private final Progress progress;
    private final RobotLoss policy;
    private final long stepTimeoutMs;
    private final long stepTimeoutNanos;
    private final LongSupplier clock;
    private final RunListener listener;
    /** Publishes the status; run before a log line about a robot, so whoever reads the line sees its state. */
    private final Runnable publish;
    /** Robots whose departure waits for the end of the step under way, in the order they left. */
    private final List<Slot> leaving = new ArrayList<>();
    /** Robots that left mid-run, in the order they did. */
    private final List<Departure> departures = new ArrayList<>();
    /** Each robot's request for the step being resolved, by index; refilled at each step (the core reads it twice). */
    private StepRequest[] batch = new StepRequest[0];
    /** Requests in for the step being collected. */
    private int arrived;
    /** Changes of who is in the run and in which state, so far: the status is published anew when it moves. */
    private long version;
    /** Every robot in the world is away, and that has been said once. */
    private boolean everyoneAwayTold;
    private SimulationCore core;

    /** Every robot {@code spec} names, expected. */
    Roster(WorldSpec spec, Progress progress, Settings settings, LongSupplier clock, RunListener listener,
            Runnable publish) {
        this.progress = progress;
        this.policy = settings.onRobotLoss();
        this.stepTimeoutMs = settings.stepTimeoutMs();
        this.stepTimeoutNanos = stepTimeoutMs <= 0 ? Long.MAX_VALUE : stepTimeoutMs * 1_000_000L;
        this.clock = clock;
        this.listener = listener;
        this.publish = publish;
        for (WorldSpec.RobotSpec r : spec.robots()) {
            add(r.name(), null, Slot.State.EXPECTED);
        }
    }

    // ---- questions -------------------------------------------------------------------------------------------

    Slot get(int index) {
        return slots.get(index);
    }

    /** The slot {@code peer} speaks for now, or null (it never said hello, or another has taken over). */
    Slot of(RobotPeer peer) {
        int i = peer.index();
        if (i < 0 || i >= slots.size()) {
            return null;
        }
        Slot s = slots.get(i);
        return s.peer == peer ? s : null;
    }

    int size() {
        return slots.size();
    }

    List<Slot> all() {
        return slots;
    }

    int count(Slot.State state) {
        return counts[state.ordinal()];
    }

    /** Changes of who is in the run and in which state, so far. */
    long version() {
        return version;
    }

    /** True when every robot the file names has said hello (before the start). */
    boolean allConnected() {
        return count(Slot.State.CONNECTED) == slots.size();
    }

    /** True while a robot is in the world without taking part. */
    boolean anyAway() {
        return count(Slot.State.HELD) + count(Slot.State.WAITED) + count(Slot.State.RETURNING)
                + count(Slot.State.JOINING) > 0;
    }

    /**
     * True while the world waits for a lost robot ({@code WAIT}): one that has not come back, or whose new
     * connection has not taken part yet (under {@code WAIT} every returning robot was waited for).
     */
    boolean worldWaits() {
        return count(Slot.State.WAITED) > 0 || policy == RobotLoss.WAIT && count(Slot.State.RETURNING) > 0;
    }

    /** True once every robot in the world is away, and the world waits until one comes back or joins. */
    boolean everyoneAway() {
        return everyoneAwayTold;
    }

    /** True when every running robot's request for the step being collected is in. */
    boolean requestsIn() {
        return arrived >= count(Slot.State.RUNNING);
    }

    /** Every robot's name now, in world order. */
    List<String> names() {
        List<String> names = new ArrayList<>(slots.size());
        for (Slot s : slots) {
            names.add(s.name);
        }
        return names;
    }

    /** Every robot and its state now, in world order (for the control port). */
    List<RobotState> states() {
        List<RobotState> states = new ArrayList<>(slots.size());
        for (Slot s : slots) {
            boolean dated = s.state.away() || s.state == Slot.State.GONE;
            states.add(new RobotState(s.name, s.state.label, dated ? s.sinceStep : -1));
        }
        return List.copyOf(states);
    }

    /** Robots that left mid-run, in the order they did. */
    List<Departure> departures() {
        return departures;
    }

    /** Before the start: what each robot said it is in its hello, by index (null: not connected yet). */
    RobotProperties[] said() {
        RobotProperties[] said = new RobotProperties[slots.size()];
        for (Slot s : slots) {
            said[s.index] = s.properties;
        }
        return said;
    }

    // ---- before the start ------------------------------------------------------------------------------------

    /** Robot {@code s} of the file said hello on {@code peer}, as {@code properties}; it waits for the start. */
    void connect(Slot s, RobotPeer peer, RobotProperties properties) {
        s.peer = peer;
        s.properties = properties;
        set(s, Slot.State.CONNECTED);
        LOG.info("robot {} connected ({} of {})", s.name, count(Slot.State.CONNECTED), slots.size());
    }

    /** The run starts in {@code world}: every robot takes part. */
    void start(SimulationCore world) {
        this.core = world;
        for (Slot s : slots) {
            set(s, Slot.State.RUNNING);
        }
    }

    /** Step 0 goes out to every running robot; one that cannot take it is lost. Then robots waiting to come back take part. */
    void begin() {
        for (Slot s : slots) {
            if (s.running()) {
                try {
                    s.peer.begin(0);
                } catch (IOException e) {
                    drop(s, "could not send it the first step: " + e.getMessage());
                }
            }
        }
        bringBackReturning();
    }

    // ---- collecting the step ---------------------------------------------------------------------------------

    /** A robot's request for the step being collected; one out of turn drops it. */
    void request(RobotPeer peer, StepRequest request) {
        Slot s = of(peer);
        if (s == null || !s.running() || progress.over() || core == null) {
            return; // gone already, or the run is over: nothing to do with it
        }
        long step = progress.step();
        if (progress.phase() != Progress.Phase.COLLECTING || request.step() != step || s.request != null) {
            drop(s, "sent a request for step " + request.step() + " out of turn (step " + step + " is due)");
            return;
        }
        s.request = request;
        arrived++;
    }

    /** Every robot's request for the step that is about to be resolved (each slot's is taken). */
    StepRequest[] takeRequests() {
        if (batch.length != slots.size()) {
            batch = new StepRequest[slots.size()];
        }
        for (int i = 0; i < batch.length; i++) {
            Slot s = slots.get(i);
            batch[i] = s.request;
            s.request = null;
        }
        arrived = 0;
        return batch;
    }

    /** The step just resolved is complete: what each robot asked in it becomes its view. */
    void resolved() {
        for (int i = 0; i < batch.length; i++) {
            slots.get(i).released = batch[i];
        }
    }

    /** The responses of the step just released went out: departures held back take effect, returning robots take part. */
    void stepReleased() {
        applyLeaving();
        bringBackReturning();
    }

    /** Every robot in the world is away: the world waits (said once) until one comes back or joins. */
    void waitForAnyone() {
        if (!everyoneAwayTold) {
            everyoneAwayTold = true;
            LOG.warn("every robot is away at step {}: the world waits until one comes back",
                    StepNumbers.shown(progress.step()));
        }
    }

    /**
     * Deadlines at {@code now}, while a step is collected: a robot the world waits for that has not come back
     * within the step timeout is removed; a running robot whose request is not in within the step timeout of
     * {@code releasedNanos} (or of its return) is dropped ({@code inWorldOrder}: only the first such, the one a
     * reader in world order waits for).
     */
    void late(long now, long releasedNanos, boolean inWorldOrder) {
        if (count(Slot.State.WAITED) > 0) {
            for (Slot s : slots) {
                if (s.state == Slot.State.WAITED && now - s.awayNanos > stepTimeoutNanos) {
                    leaveWorld(s, "did not come back within " + stepTimeoutMs + " ms (step timeout)");
                }
            }
        }
        if (now - releasedNanos > stepTimeoutNanos) {
            for (Slot s : slots) {
                if (s.running() && s.request == null && (s.backNanos == 0 || now - s.backNanos > stepTimeoutNanos)) {
                    drop(s, "sent no request for step " + StepNumbers.shown(progress.step()) + " within "
                            + stepTimeoutMs + " ms (step timeout): its control code made no call of the robot (move, "
                            + "turn, sleep, ...) since its last step, or its process stopped answering; make each pass "
                            + "of its loop call the robot, robot.sleep(1) at least");
                    if (inWorldOrder) {
                        break; // the stepper reads in world order: only the robot it waits for is late
                    }
                }
            }
        }
    }

    // ---- robots leaving and coming back ----------------------------------------------------------------------

    /** A robot's connection has closed or failed. */
    void left(RobotPeer peer, String why) {
        Slot s = of(peer);
        if (s == null || progress.over()) {
            return;
        }
        if (progress.phase() == Progress.Phase.WAITING) {
            s.peer = null;
            s.properties = null;
            set(s, Slot.State.EXPECTED);
            LOG.warn("robot {} left before the start ({}); waiting for it again", s.name, Printable.of(why));
            return;
        }
        switch (s.state) {
            case JOINING -> set(s, Slot.State.RUNNING); // it went before it took part: lost like any robot
            case HELD, WAITED, GONE -> {
                return;
            }
            case RETURNING -> {
                set(s, awayState()); // the new connection went before it took over: away as before
                return;
            }
            default -> s.takeover = false; // (a take-over said hello before the old loss took effect, and went too)
        }
        leave(s, why, false);
    }

    /** The loop drops robot {@code s} (closes its connection, or tells it its end) and it leaves, for {@code why}. */
    void drop(Slot s, String why) {
        s.peer.drop();
        leave(s, why, false);
    }

    /**
     * The control port's {@code remove}: robot {@code s} is told its end (unless its connection has closed) and
     * leaves the world for good, whatever the loss policy; at the end of the step under way if one is.
     */
    void remove(Slot s) {
        if (!s.peer.closed()) { // (not dropped: what it sends is ignored from now on, and it closes when told)
            s.peer.end(new SimulationEnd(progress.step() - 1, "removed from the simulation from the control port"),
                    s.peer.begun());
        }
        leave(s, "removed from the control port", true);
    }

    /**
     * Robot {@code s} no longer takes part: it is removed ({@code forGood}, or {@code --on-robot-loss REMOVE}),
     * or held for its return. While a step is being resolved or released (its request is already in that
     * step) this happens at the end of that step instead.
     */
    void leave(Slot s, String why, boolean forGood) {
        if (progress.midStep()) {
            if (s.leaving == null) {
                s.leaving = new Slot.Leaving(why, forGood);
                leaving.add(s);
                LOG.info("robot {} lost during step {} ({}); it stops taking part at the step's end",
                        s.name, StepNumbers.shown(progress.current()), Printable.of(why));
            } else if (forGood) {
                s.leaving = new Slot.Leaving(s.leaving.why(), true);
            }
            return;
        }
        leaveNow(s, why, forGood);
    }

    /** As {@link #leave}, between steps. */
    private void leaveNow(Slot s, String why, boolean forGood) {
        if (s.state.away()) {
            if (forGood) {
                leaveWorld(s, Printable.of(why));
            }
            return;
        }
        if (s.request != null) {
            s.request = null;
            arrived--;
        }
        String safe = Printable.of(why);
        if (forGood || policy == RobotLoss.REMOVE) {
            leaveWorld(s, safe);
            return;
        }
        long step = progress.step();
        s.sinceStep = step;
        s.awayNanos = clock.getAsLong();
        set(s, s.takeover ? Slot.State.RETURNING : awayState());
        s.takeover = false;
        core.away(s.index, true);
        publish.run(); // (before the log line: whoever reads it sees the state)
        LOG.warn("robot {} lost at step {} ({}); it stands where it is until a robot process says hello as {}{}",
                s.name, StepNumbers.shown(step), safe, s.name, policy == RobotLoss.WAIT
                        ? ", and the world waits for it" + limit() : "");
        listener.robotHeld(s.name, step, safe);
    }

    /** Where a lost robot stands under the loss policy (HOLD or WAIT). */
    private Slot.State awayState() {
        return policy == RobotLoss.WAIT ? Slot.State.WAITED : Slot.State.HELD;
    }

    private String limit() {
        return stepTimeoutMs > 0 ? " (at most " + stepTimeoutMs + " ms: the step timeout)" : "";
    }

    /** Takes robot {@code s} out of the world for good; {@code why} is safe to print. */
    private void leaveWorld(Slot s, String why) {
        long step = progress.step();
        set(s, Slot.State.GONE);
        s.takeover = false;
        s.sinceStep = step;
        core.depart(s.index);
        Departure d = new Departure(s.name, step, why);
        departures.add(d);
        publish.run();
        LOG.warn("robot {} left at step {} ({}); it is removed from the world and the others go on", d.robot(),
                StepNumbers.shown(step), why);
        listener.robotLeft(d);
    }

    /** The departures held back during the step just released take effect now (and at the end). */
    void applyLeaving() {
        if (leaving.isEmpty()) {
            return;
        }
        List<Slot> due = List.copyOf(leaving);
        leaving.clear();
        for (Slot s : due) {
            Slot.Leaving l = s.leaving;
            s.leaving = null;
            if (s.state != Slot.State.GONE) {
                leaveNow(s, l.why(), l.forGood());
            }
        }
    }

    /**
     * A new connection ({@code peer}) takes robot {@code s} over, at its pose: from the next step, or, if it is
     * still running (its old connection's loss has not taken effect), once it has left.
     */
    void takeOver(Slot s, RobotPeer peer) {
        s.peer = peer;
        version++; // (the connection that speaks for it is another now)
        if (s.running()) {
            s.takeover = true; // (it leaves at the end of this step; the new connection takes over then)
        } else {
            set(s, Slot.State.RETURNING);
        }
        publish.run();
    }

    /** Robot {@code name} joins the running world by {@code rule} on {@code peer}; it takes part from the next step. */
    Slot join(String name, JoinRule rule, RobotPeer peer, RobotProperties properties) {
        Slot s = add(name, rule, Slot.State.JOINING);
        s.peer = peer;
        s.properties = properties;
        s.sinceStep = progress.step();
        return s;
    }

    /** Robots whose new connection, or whose join, waits for the next step take part from the step being collected. */
    private void bringBackReturning() {
        if (count(Slot.State.RETURNING) + count(Slot.State.JOINING) == 0) {
            return;
        }
        for (Slot s : slots) {
            if (s.state == Slot.State.RETURNING || s.state == Slot.State.JOINING) {
                bringBack(s);
            }
        }
    }

    /** Robot {@code s}'s new connection takes part from the step being collected: it gets that step's number. */
    void bringBack(Slot s) {
        boolean joined = s.state == Slot.State.JOINING;
        long step = progress.step();
        set(s, Slot.State.RUNNING);
        core.away(s.index, false);
        everyoneAwayTold = false;
        publish.run();
        s.backNanos = clock.getAsLong(); // its step timeout runs from now, as the others' did from their step
        if (joined) {
            LOG.info("robot {} takes part from step {}", s.name, StepNumbers.shown(step));
        } else {
            LOG.info("robot {} is back at step {}, where it stood since step {}", s.name, StepNumbers.shown(step),
                    StepNumbers.shown(s.sinceStep));
            listener.robotReturned(s.name, step);
        }
        try {
            s.peer.begin(step);
        } catch (IOException e) {
            drop(s, "could not send it step " + step + ": " + e.getMessage());
        }
    }

    // ---- the end ---------------------------------------------------------------------------------------------

    /** The run is over: every robot still in it is told {@code end} (those that were told it with their response are not). */
    void end(SimulationEnd end, boolean told) {
        if (told) {
            return;
        }
        for (Slot s : slots) {
            if (s.peer != null && !s.peer.closed() && s.state != Slot.State.GONE) {
                s.peer.end(end, s.peer.begun());
            }
        }
    }

    // ---- the table -------------------------------------------------------------------------------------------

    /** A robot more, at the end of the list. */
    private Slot add(String name, JoinRule rule, Slot.State state) {
        Slot s = new Slot(slots.size(), name, rule, state);
        slots.add(s);
        counts[state.ordinal()]++;
        version++;
        return s;
    }

    /** The one place a robot's state changes, as the table allows. */
    private void set(Slot slot, Slot.State to) {
        if (!slot.state.leadsTo(to)) {
            throw new IllegalStateException("robot " + slot.name + " cannot go from " + slot.state + " to " + to);
        }
        counts[slot.state.ordinal()]--;
        counts[to.ordinal()]++;
        slot.state = to;
        version++;
    }
}
