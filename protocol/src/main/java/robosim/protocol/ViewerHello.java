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
 * frames a second has no use for more. A viewer may watch one robot by name: it then gets that robot's
 * {@link RobotView} after each update (the robot-specific viewer).
 */
public final class ViewerHello implements java.io.Externalizable {
    private int protocolVersion = Protocol.VERSION;
    private boolean everyStep;
    private int maxUpdatesPerSecond;
    private String watch = "";

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

    /** As above, watching the robot named {@code watch} ("" for none): a {@link RobotView} follows each update. */
    public ViewerHello(boolean everyStep, int maxUpdatesPerSecond, String watch) {
        this(everyStep, maxUpdatesPerSecond);
        if (watch == null) {
            throw new IllegalArgumentException("watch must not be null (\"\" for none)");
        }
        this.watch = watch;
    }

    /** The robot this viewer watches ("" for none). */
    public String watch() {
        return watch;
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
        out.writeUTF(watch);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        protocolVersion = in.readInt();
        if (protocolVersion != Protocol.VERSION) {
            return;
        }
        everyStep = in.readBoolean();
        maxUpdatesPerSecond = Math.max(0, in.readInt());
        watch = in.readUTF();
    }
}
