package robosim.environment.run;

import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryWorld;
import robosim.protocol.SimulationEnd;

/**
 * A Geometry process as the loop's {@link GeometryLink} sees it: what it is asked to do, each handed to the thread
 * that owns its connection ({@link GeometryClientWorker}); its answers come back as events. Loop thread.
 */
public interface GeometryPeer {
    /** Send it the world (when the run starts, when it takes over mid-run, after robots joined). */
    void sendWorld(GeometryWorld world);

    /** Resolve {@code request}; the answer comes back as a {@link LoopEvent.GeometryAnswer}. */
    void resolve(GeometryStepRequest request);

    /** Tell it the simulation is over, after whatever it is doing. */
    void end(SimulationEnd end);

    /** Close its connection at once. */
    void drop();
}
