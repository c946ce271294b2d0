package robosim.environment.core;

import java.util.List;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotProperties;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/** Test fixture: a {@link SimulationCore} (no metrics) whose steps are resolved by the geometry library in-process. */
public final class InProcessSteps {
    private final SimulationCore core;
    private final InProcessGeometry geometry;

    private InProcessSteps(SimulationCore core) {
        this.core = core;
        this.geometry = new InProcessGeometry(core.map().geometryWorld());
    }

    public static InProcessSteps of(WorldSpec spec, List<RobotProperties> properties) {
        return new InProcessSteps(new SimulationCore(spec, properties));
    }

    /** Step k, resolved in-process. */
    public void step(long k, StepRequest[] requests) throws ProtocolException {
        core.step(k, requests, geometry);
    }

    public StepResponse response(int robot) {
        return core.response(robot);
    }

    public List<String> tags() {
        return core.tags();
    }

    public PoseUpdate viewerUpdate() {
        return core.viewerUpdate();
    }

    public long messagesDelivered() {
        return core.messagesDelivered();
    }

    public long messagesUndeliverable() {
        return core.messagesUndeliverable();
    }

    public long messagesOutOfRange() {
        return core.messagesOutOfRange();
    }
}
