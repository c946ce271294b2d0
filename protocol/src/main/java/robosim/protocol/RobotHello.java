package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Robot -> Environment, once, first on the robot port: protocol version, robot name and the
 * robot's properties, or none: "any type", the robot takes the type the environment file gives it (its
 * {@link RobotWelcome#type()}). Answered by {@link RobotWelcome}. When the version differs nothing after it
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

    /** A robot of any type: it takes the file's ({@link RobotWelcome#type()}). */
    public static RobotHello anyType(String name) {
        return new RobotHello(name, null);
    }

    /** True if the robot takes the type the file gives it (it sent no properties). */
    public boolean anyType() {
        return protocolVersion == Protocol.VERSION && properties == null;
    }

    public int protocolVersion() {
        return protocolVersion;
    }

    /** Null when {@link #protocolVersion()} is not {@link Protocol#VERSION}. */
    public String name() {
        return name;
    }

    /** Null when {@link #protocolVersion()} is not {@link Protocol#VERSION}, or for {@link #anyType()}. */
    public RobotProperties properties() {
        return properties;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeInt(protocolVersion);
        out.writeUTF(name);
        out.writeBoolean(properties == null);
        if (properties != null) {
            properties.write(out);
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        protocolVersion = in.readInt();
        if (protocolVersion != Protocol.VERSION) {
            return;
        }
        name = in.readUTF();
        properties = in.readBoolean() ? null : RobotProperties.read(in);
    }
}
