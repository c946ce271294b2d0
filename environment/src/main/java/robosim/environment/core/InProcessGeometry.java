package robosim.environment.core;

import java.util.List;
import robosim.geometry.GeometryEngine;
import robosim.geometry.StaticWorld;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.GeometryWorld;

/** {@code --no-geometry} (the original's GEOMETRY_USED off): the geometry library, called directly. */
public final class InProcessGeometry implements SimulationCore.Geometry {
    private final GeometryEngine engine;
    private final GeometryStepResponse response;

    public InProcessGeometry(GeometryWorld world) {
        this.engine = new GeometryEngine(world, Runtime.getRuntime().availableProcessors() > 1
                ? GeometryEngine.DEFAULT_PARALLEL_FROM : 0);
        this.response = engine.newResponse();
    }

    /** The answer to {@code request}; valid until the next call. */
    @Override
    public GeometryStepResponse resolve(GeometryStepRequest request) {
        engine.step(request, response);
        return response;
    }
}
