package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/** Geometry -> Environment, once, first on the geometry port: the protocol version. */
public final class GeometryHello implements java.io.Externalizable {
    private int protocolVersion = Protocol.VERSION;

    public GeometryHello() {
    }

    public int protocolVersion() {
        return protocolVersion;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeInt(protocolVersion);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        protocolVersion = in.readInt();
    }
}
