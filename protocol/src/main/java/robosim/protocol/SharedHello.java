package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Robot process -> Environment, first on a shared connection (one TCP connection for several robots of
 * one process): the protocol version and how many robots follow, each as its own {@link RobotHello}
 * (read under the stranger's byte cap one by one). The robots are numbered by their place in that list,
 * their slot on the connection; every later frame names robots by slot. Answered by one
 * {@link SharedReplies} frame holding a {@link RobotWelcome} (accepted or refused) for every slot.
 */
public final class SharedHello implements java.io.Externalizable {
    private int protocolVersion = Protocol.VERSION;
    private int robots;

    public SharedHello() {
    }

    public SharedHello(int robots) {
        this.robots = robots;
    }

    public int protocolVersion() {
        return protocolVersion;
    }

    /** How many {@link RobotHello}s follow, 1 to 2048 (0 when the version is not this one's). */
    public int robots() {
        return robots;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeInt(protocolVersion);
        out.writeInt(robots);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        protocolVersion = in.readInt();
        if (protocolVersion != Protocol.VERSION) {
            return;
        }
        robots = Limits.checkCount("robots on one shared connection", in.readInt(), Limits.MAX_ROBOTS_PER_CONNECTION);
        if (robots == 0) {
            throw new ProtocolException("robots on one shared connection must be at least 1, got 0");
        }
    }
}
