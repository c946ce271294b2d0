package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Viewer -> Environment, once, first on the viewer port: protocol version and mode. A live viewer
 * gets only the newest poses (a slow one skips steps and never slows the robots). A recording
 * viewer ({@code everyStep}) gets every step's update in order; when it falls more than a bounded
 * number of updates behind, the simulation waits for it. A live viewer may also cap how many
 * updates a second it wants ({@code maxUpdatesPerSecond}, 0 = no cap): a window that draws 30
 * frames a second has no use for more.
 */
public final class ViewerHello implements java.io.Externalizable {
    private int protocolVersion = Protocol.VERSION;
    private boolean everyStep;
    private int maxUpdatesPerSecond;

    public ViewerHello() {
    }

    public ViewerHello(boolean everyStep) {
        this(everyStep, 0);
    }

    public ViewerHello(boolean everyStep, int maxUpdatesPerSecond) {
        if (maxUpdatesPerSecond < 0) {
            throw new IllegalArgumentException("maxUpdatesPerSecond must be >= 0, got " + maxUpdatesPerSecond);
        }
        this.everyStep = everyStep;
        this.maxUpdatesPerSecond = maxUpdatesPerSecond;
    }

    /** Updates per second a live viewer wants at most; 0 = as many as there are steps. */
    public int maxUpdatesPerSecond() {
        return maxUpdatesPerSecond;
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
        out.writeInt(maxUpdatesPerSecond);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        protocolVersion = in.readInt();
        if (protocolVersion != Protocol.VERSION) {
            return;
        }
        everyStep = in.readBoolean();
        maxUpdatesPerSecond = Math.max(0, in.readInt());
    }
}
