package robosim.environment.net;

import java.util.ArrayList;
import java.util.List;
import robosim.environment.core.EnvironmentMap;
import robosim.environment.core.WorldSpec;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotModels;
import robosim.protocol.RobotProperties;
import robosim.protocol.WorldSnapshot;

/** What a viewer that joins before the start sees: every robot at its start pose, as it said it is or as the file expects it. */
final class StartSnapshot {
    private StartSnapshot() {
    }

    /** {@code registered[i]}: robot i's properties from its hello, or null if it has not said hello yet. */
    static WorldSnapshot of(WorldSpec spec, RobotProperties[] registered) {
        int n = spec.robots().size();
        List<RobotProperties> props = new ArrayList<>(n);
        double[] x = new double[n];
        double[] y = new double[n];
        double[] h = new double[n];
        for (int i = 0; i < n; i++) {
            WorldSpec.RobotSpec r = spec.robots().get(i);
            props.add(registered[i] != null ? registered[i] : expected(r));
            x[i] = r.xMm();
            y[i] = r.yMm();
            h[i] = r.headingDeg();
        }
        return EnvironmentMap.snapshot(spec, props, new PoseUpdate(-1, x, y, h));
    }

    /** What a robot not yet connected looks like: its model, or a disc of the file's radius. */
    private static RobotProperties expected(WorldSpec.RobotSpec r) {
        RobotProperties model = RobotModels.byName(r.type());
        return model != null ? model : new RobotProperties(r.type(), r.radiusMm(), 1, 1, List.of());
    }
}
