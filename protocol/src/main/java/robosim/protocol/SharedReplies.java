package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.Arrays;
import java.util.List;

/**
 * Environment -> robot process on a shared connection: everything for its robots since the last frame,
 * in order, each entry naming its robot by slot. {@link Kind#WELCOME}: the answer to its hello (accepted
 * or refused); {@link Kind#STEP}: its first step number; {@link Kind#RESPONSE}: its response and the
 * next step number ({@link Protocol#END_OF_SIMULATION} when an {@link Kind#END} follows); {@link Kind#END}:
 * the simulation is over for it, and why. The Environment reuses one frame per connection.
 */
public final class SharedReplies implements java.io.Externalizable {
    /** What an entry says. */
    public enum Kind { WELCOME, STEP, RESPONSE, END }

    private static final Kind[] KINDS = Kind.values();
    /** Entries one frame may hold: a welcome, a first step, a response and an end for every robot. */
    public static final int MAX_ENTRIES = 4 * Limits.MAX_ROBOTS_PER_CONNECTION;

    private int count;
    private byte[] kinds = new byte[8];
    private int[] slots = new int[8];
    private long[] steps = new long[8];
    private java.io.Externalizable[] payloads = new java.io.Externalizable[8];

    public SharedReplies() {
    }

    public void welcome(int slot, RobotWelcome welcome) {
        add(Kind.WELCOME, slot, 0, welcome);
    }

    public void step(int slot, long step) {
        add(Kind.STEP, slot, step, null);
    }

    public void response(int slot, StepResponse response, long nextStep) {
        add(Kind.RESPONSE, slot, nextStep, response);
    }

    public void end(int slot, SimulationEnd end) {
        add(Kind.END, slot, 0, end);
    }

    private void add(Kind kind, int slot, long step, java.io.Externalizable payload) {
        if (count == slots.length) {
            int grown = Math.max(8, count * 2);
            kinds = Arrays.copyOf(kinds, grown);
            slots = Arrays.copyOf(slots, grown);
            steps = Arrays.copyOf(steps, grown);
            payloads = Arrays.copyOf(payloads, grown);
        }
        kinds[count] = (byte) kind.ordinal();
        slots[count] = slot;
        steps[count] = step;
        payloads[count++] = payload;
    }

    /** Empties the frame once it is written (the writer's). */
    public void clear() {
        Arrays.fill(payloads, 0, count, null);
        count = 0;
    }

    public int count() {
        return count;
    }

    public Kind kind(int i) {
        return KINDS[kinds[i]];
    }

    public int slot(int i) {
        return slots[i];
    }

    /** A STEP entry's step number, or a RESPONSE entry's next one. */
    public long step(int i) {
        return steps[i];
    }

    public RobotWelcome welcome(int i) {
        return (RobotWelcome) payloads[i];
    }

    public StepResponse response(int i) {
        return (StepResponse) payloads[i];
    }

    public SimulationEnd end(int i) {
        return (SimulationEnd) payloads[i];
    }

    /**
     * A {@code WELCOME}'s body starts with a boolean: true when its robot names are those of the frame's
     * previous accepted welcome and left out (every robot of a connection gets the world's names: once per frame,
     * not once per robot).
     */
    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeInt(count);
        List<String> names = null;
        for (int i = 0; i < count; i++) {
            out.writeByte(kinds[i]);
            out.writeInt(slots[i]);
            switch (KINDS[kinds[i]]) {
                case WELCOME -> {
                    RobotWelcome w = (RobotWelcome) payloads[i];
                    boolean same = w.isAccepted() && names != null
                            && (names == w.robotNames() || names.equals(w.robotNames()));
                    out.writeBoolean(same);
                    w.write(out, !same);
                    names = w.isAccepted() ? w.robotNames() : names;
                }
                case STEP -> out.writeLong(steps[i]);
                case RESPONSE -> {
                    out.writeLong(steps[i]);
                    payloads[i].writeExternal(out);
                }
                case END -> payloads[i].writeExternal(out);
            }
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        count = Limits.checkCount("entries in one frame", in.readInt(), MAX_ENTRIES);
        kinds = new byte[Math.max(8, count)];
        slots = new int[kinds.length];
        steps = new long[kinds.length];
        payloads = new java.io.Externalizable[kinds.length];
        List<String> names = null;
        for (int i = 0; i < count; i++) {
            byte k = in.readByte();
            if (k < 0 || k >= KINDS.length) {
                throw new ProtocolException("entry kind must be in [0, " + (KINDS.length - 1) + "], got " + k);
            }
            kinds[i] = k;
            slots[i] = in.readInt();
            switch (KINDS[k]) {
                case WELCOME -> {
                    boolean same = in.readBoolean();
                    if (same && names == null) {
                        throw new ProtocolException("a welcome takes the robot names of a welcome before it, "
                                + "and there is none");
                    }
                    RobotWelcome w = new RobotWelcome();
                    w.read(in, same ? names : null);
                    names = w.isAccepted() ? w.robotNames() : names;
                    payloads[i] = w;
                }
                case STEP -> steps[i] = in.readLong();
                case RESPONSE -> {
                    steps[i] = in.readLong();
                    StepResponse r = new StepResponse();
                    r.readExternal(in);
                    payloads[i] = r;
                }
                case END -> {
                    SimulationEnd e = new SimulationEnd();
                    e.readExternal(in);
                    payloads[i] = e;
                }
            }
        }
    }
}
