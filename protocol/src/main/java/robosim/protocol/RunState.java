package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Environment -> viewer, whenever the run changes between running and held (pause, resume, the
 * hold before step 0 of a run started paused), and once right after the {@link WorldSnapshot}: what
 * the run is doing now, so a viewer that gets no updates can tell a paused run from a slow one.
 * {@code step}: steps whose responses have gone out. Added in protocol version 3.
 */
public final class RunState implements java.io.Externalizable {
    /** What the run is doing; the wire value is the ordinal. */
    public enum Phase { WAITING, RUNNING, PAUSED }

    private static final Phase[] PHASES = Phase.values();

    private long step;
    private Phase phase = Phase.WAITING;

    public RunState() {
    }

    public RunState(long step, Phase phase) {
        if (phase == null) {
            throw new IllegalArgumentException("phase must not be null");
        }
        this.step = step;
        this.phase = phase;
    }

    public long step() {
        return step;
    }

    public Phase phase() {
        return phase;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeByte(phase.ordinal());
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        int p = in.readUnsignedByte();
        if (p >= PHASES.length) {
            throw new ProtocolException("run state phase must be 0.." + (PHASES.length - 1) + ", got " + p);
        }
        phase = PHASES[p];
    }

    @Override
    public String toString() {
        return phase + " at step " + step;
    }
}
