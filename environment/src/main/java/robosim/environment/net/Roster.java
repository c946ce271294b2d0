package robosim.environment.net;

import java.util.ArrayList;
import java.util.List;
import robosim.environment.core.JoinRule;
import robosim.environment.core.WorldSpec;
import robosim.protocol.StepRequest;

/**
 * The run's robots, one {@link RobotSlot} each, in world order (the file's robots, then those that joined,
 * in the order they did), and how many are in each state, kept as states change so that the loop's
 * questions ("is everyone here?", "does the world wait?") cost nothing per event. Loop thread only.
 */
final class Roster {
    private final List<RobotSlot> slots = new ArrayList<>();
    private final int[] counts = new int[RobotSlot.State.values().length];
    /** Each robot's request for the step being resolved, by index; refilled at each step (the core reads it twice). */
    private StepRequest[] batch = new StepRequest[0];

    /** Every robot the file names, expected. */
    Roster(WorldSpec spec) {
        for (WorldSpec.RobotSpec r : spec.robots()) {
            add(r.name(), null, RobotSlot.State.EXPECTED);
        }
    }

    /** A robot more, at the end of the list. */
    RobotSlot add(String name, JoinRule rule, RobotSlot.State state) {
        RobotSlot s = new RobotSlot(slots.size(), name, rule, state);
        slots.add(s);
        counts[state.ordinal()]++;
        return s;
    }

    RobotSlot get(int index) {
        return slots.get(index);
    }

    /** The slot {@code peer} speaks for now, or null (it never said hello, or another has taken over). */
    RobotSlot of(RobotPeer peer) {
        int i = peer.index();
        if (i < 0 || i >= slots.size()) {
            return null;
        }
        RobotSlot s = slots.get(i);
        return s.peer == peer ? s : null;
    }

    int size() {
        return slots.size();
    }

    List<RobotSlot> all() {
        return slots;
    }

    void set(RobotSlot slot, RobotSlot.State to) {
        counts[slot.state.ordinal()]--;
        counts[to.ordinal()]++;
        slot.state = to;
    }

    int count(RobotSlot.State state) {
        return counts[state.ordinal()];
    }

    /** True while a robot is in the world without taking part. */
    boolean anyAway() {
        return count(RobotSlot.State.HELD) + count(RobotSlot.State.WAITED) + count(RobotSlot.State.RETURNING)
                + count(RobotSlot.State.JOINING) > 0;
    }

    /**
     * True while the world waits for a lost robot ({@code WAIT}): one that has not come back, or whose new
     * connection has not taken part yet (under {@code WAIT} every returning robot was waited for).
     */
    boolean worldWaits(RobotLoss policy) {
        return count(RobotSlot.State.WAITED) > 0 || policy == RobotLoss.WAIT && count(RobotSlot.State.RETURNING) > 0;
    }

    /** Every robot's request for the step that is about to be resolved (each slot's is taken). */
    StepRequest[] takeRequests() {
        if (batch.length != slots.size()) {
            batch = new StepRequest[slots.size()];
        }
        for (int i = 0; i < batch.length; i++) {
            RobotSlot s = slots.get(i);
            batch[i] = s.request;
            s.request = null;
        }
        return batch;
    }

    /** The step just resolved is complete: what each robot asked in it becomes its view. */
    void resolved() {
        for (int i = 0; i < batch.length; i++) {
            slots.get(i).released = batch[i];
        }
    }

    /** Every robot's name now, in world order. */
    List<String> names() {
        List<String> names = new ArrayList<>(slots.size());
        for (RobotSlot s : slots) {
            names.add(s.name);
        }
        return names;
    }

    /** Every robot and its state now, in world order (for the control port). */
    List<RobotState> states() {
        List<RobotState> states = new ArrayList<>(slots.size());
        for (RobotSlot s : slots) {
            boolean dated = s.state.away() || s.state == RobotSlot.State.GONE;
            states.add(new RobotState(s.name, s.state.label, dated ? s.sinceStep : -1));
        }
        return List.copyOf(states);
    }
}
