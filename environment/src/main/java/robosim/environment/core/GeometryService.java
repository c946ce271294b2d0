package robosim.environment.core;

import java.io.IOException;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;

/**
 * Resolves one step's ACTION and SONAR requests: the Geometry process over its socket
 * ({@code GeometryClientWorker}) or the same library in-process ({@link InProcessGeometry}).
 */
public interface GeometryService {
    /** The answer to {@code request}; valid until the next call. */
    GeometryStepResponse resolve(GeometryStepRequest request) throws IOException;
}
