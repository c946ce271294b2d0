package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Viewer -> Environment, once, first on the viewer port: protocol version and mode. A live viewer
 * gets only the newest poses (a slow one skips steps and never slows the robots). A recording
 * viewer ({@code everyStep}) gets every step's update in order; when it falls more than a bounded
 * number of updates behind, the simulation waits for it.
 */
public final class ViewerHello implements java.io.Externalizable {
    private int protocolVersion = Protocol.VERSION;
    private boolean everyStep;

    public ViewerHello() {
    }

    public ViewerHello(boolean everyStep) {
        this.everyStep = everyStep;
    }

    public int protocolVersion() {
        return protocolVersion;
    }

    public boolean everyStep() {
        return everyStep;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeInt(protocolVersion);
        out.writeBoolean(everyStep);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        protocolVersion = in.readInt();
        if (protocolVersion != Protocol.VERSION) {
            return;
        }
        everyStep = in.readBoolean();
    }
}
