package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Robot -> Environment, once, first on the robot port: protocol version, robot name and the
 * robot's properties. Answered by {@link RobotWelcome}. When the version differs nothing after it
 * is read (its layout may differ), and the Environment refuses the robot with a reason.
 */
public final class RobotHello implements java.io.Externalizable {
    private int protocolVersion;
    private String name;
    private RobotProperties properties;

    public RobotHello() {
    }

    public RobotHello(String name, RobotProperties properties) {
        this.protocolVersion = Protocol.VERSION;
        this.name = name;
        this.properties = properties;
    }

    public int protocolVersion() {
        return protocolVersion;
    }

    /** Null when {@link #protocolVersion()} is not {@link Protocol#VERSION}. */
    public String name() {
        return name;
    }

    /** Null when {@link #protocolVersion()} is not {@link Protocol#VERSION}. */
    public RobotProperties properties() {
        return properties;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeInt(protocolVersion);
        out.writeUTF(name);
        properties.write(out);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        protocolVersion = in.readInt();
        if (protocolVersion != Protocol.VERSION) {
            return;
        }
        name = in.readUTF();
        properties = RobotProperties.read(in);
    }
}
