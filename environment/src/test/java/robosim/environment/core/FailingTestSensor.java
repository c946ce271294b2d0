package robosim.environment.core;

import java.util.List;
import robosim.devices.RobotSensor;
import robosim.devices.SensorContext;
import robosim.devices.SensorInfo;
import robosim.devices.SensorValues;

/** A sensor that always fails: the run must go on. */
public final class FailingTestSensor extends RobotSensor {
    public FailingTestSensor() {
        super(new SensorInfo("failing", "fails", List.of(), "none", "1", false, SensorInfo.Display.VALUES));
    }

    @Override
    public SensorValues values() {
        return new SensorValues(0, 0, 0, "1");
    }

    @Override
    public double[] generateSensorResponse(SensorContext context) {
        throw new IllegalStateException("out of order");
    }
}
