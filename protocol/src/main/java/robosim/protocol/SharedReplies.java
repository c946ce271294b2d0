package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.Arrays;

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
            kinds = Arrays.copyOf(kinds, count * 2);
            slots = Arrays.copyOf(slots, count * 2);
            steps = Arrays.copyOf(steps, count * 2);
            payloads = Arrays.copyOf(payloads, count * 2);
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

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeInt(count);
        for (int i = 0; i < count; i++) {
            out.writeByte(kinds[i]);
            out.writeInt(slots[i]);
            if (kinds[i] == Kind.STEP.ordinal() || kinds[i] == Kind.RESPONSE.ordinal()) {
                out.writeLong(steps[i]);
            }
            if (payloads[i] != null) {
                payloads[i].writeExternal(out);
            }
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        count = Limits.checkCount("entries in one frame", in.readInt(), MAX_ENTRIES);
        kinds = new byte[count];
        slots = new int[count];
        steps = new long[count];
        payloads = new java.io.Externalizable[count];
        for (int i = 0; i < count; i++) {
            byte k = in.readByte();
            if (k < 0 || k >= KINDS.length) {
                throw new ProtocolException("entry kind must be in [0, " + (KINDS.length - 1) + "], got " + k);
            }
            kinds[i] = k;
            slots[i] = in.readInt();
            Kind kind = KINDS[k];
            if (kind == Kind.STEP || kind == Kind.RESPONSE) {
                steps[i] = in.readLong();
            }
            payloads[i] = switch (kind) {
                case WELCOME -> {
                    RobotWelcome w = new RobotWelcome();
                    w.readExternal(in);
                    yield w;
                }
                case RESPONSE -> {
                    StepResponse r = new StepResponse();
                    r.readExternal(in);
                    yield r;
                }
                case END -> {
                    SimulationEnd e = new SimulationEnd();
                    e.readExternal(in);
                    yield e;
                }
                case STEP -> null;
            };
        }
    }
}
