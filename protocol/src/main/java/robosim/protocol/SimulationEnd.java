package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Environment -> any client, last: the simulation is over after {@code lastStep} (-1 when no step
 * ran), and why. To a robot it follows {@link Protocol#END_OF_SIMULATION} in place of a step number.
 */
public final class SimulationEnd implements java.io.Externalizable {
    private long lastStep;
    private String reason = "";

    public SimulationEnd() {
    }

    public SimulationEnd(long lastStep, String reason) {
        this.lastStep = lastStep;
        this.reason = reason;
    }

    public long lastStep() {
        return lastStep;
    }

    public String reason() {
        return reason;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(lastStep);
        out.writeUTF(reason);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        lastStep = in.readLong();
        reason = in.readUTF();
    }
}
