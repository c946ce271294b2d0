package robosim.environment;

import picocli.CommandLine.Option;
import robosim.environment.run.GeometryLoss;

/** What the Environment does when its Geometry process is lost (a picocli mixin of environment.sh and soak.sh). */
public final class GeometryLossOption {
    @Option(names = "--on-geometry-loss", paramLabel = "POLICY", defaultValue = "IN_PROCESS",
            description = "When the Geometry process dies or hangs mid-run: IN_PROCESS (go on with in-process "
                    + "geometry, same results; the default) or WAIT (hold the step until a new Geometry process "
                    + "attaches). Either way a new Geometry process may attach and takes over.")
    private GeometryLoss policy;

    public GeometryLoss policy() {
        return policy;
    }
}
