package robosim.environment.net;

import robosim.environment.core.JoinRule;
import robosim.protocol.RobotProperties;
import robosim.protocol.StepRequest;

/**
 * One robot of the run, as the {@link Run} keeps it: its state, the connection that speaks for it, what it
 * said it is, and what it asked. Its place in the world's robot list ({@link #index}) never changes. Loop
 * thread only; the {@link Roster} changes its state (so that it can count states).
 *
 * <p>The states and their transitions:
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
 * JOINING   -&gt; RUNNING              the step being collected is its first
 *           -&gt; (as RUNNING)         lost before it took part: lost like any robot
 *           -&gt; GONE                 removed
 * </pre>
 * A robot that leaves while a step is resolved or released stays {@code RUNNING} until that step's end
 * ({@link #leaving}); a connection that says hello with its name meanwhile takes over after it
 * ({@link #takeover}).
 */
final class RobotSlot {
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
    }

    /** A departure held back until the end of the step under way; {@code forGood}: removed whatever the policy. */
    record Leaving(String why, boolean forGood) {
    }

    final int index;
    final String name;
    /** The rule it joined by; null for the file's robots. */
    final JoinRule rule;
    State state;
    /** Where the loop's messages to it go; null until it has said hello. */
    RobotPeer peer;
    /** What it said it is in its hello; null until then. */
    RobotProperties properties;
    /** Its request for the step being collected, or null. */
    StepRequest request;
    /** What it asked in the step last released (its view, the recording), or null. */
    StepRequest released;
    /** Away or gone: the first step it did not take part in. */
    long sinceStep;
    /** Away: when it went (ns), for the step timeout of a robot the world waits for. */
    long awayNanos;
    /** When it last came back (ns), 0 if never: its step timeout runs from then for the step it was given. */
    long backNanos;
    /** Its departure, held back until the end of the step under way; or null. */
    Leaving leaving;
    /** With {@link #leaving}: a new connection has said hello and takes over once it has left. */
    boolean takeover;

    RobotSlot(int index, String name, JoinRule rule, State state) {
        this.index = index;
        this.name = name;
        this.rule = rule;
        this.state = state;
    }

    /** True while it takes part in the steps (also while it leaves at the end of this one). */
    boolean running() {
        return state == State.RUNNING;
    }
}
