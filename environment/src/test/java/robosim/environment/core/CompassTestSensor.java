package robosim.environment.core;

import java.util.List;
import robosim.devices.Attribute;
import robosim.devices.Attributes;
import robosim.devices.RobotSensor;
import robosim.devices.SensorContext;
import robosim.devices.SensorInfo;
import robosim.devices.SensorValues;

/** A sensor that exists only in the tests, named by its class: heading plus a configured offset. */
public final class CompassTestSensor extends RobotSensor {
    private static final Attribute OFFSET = Attribute.number("offsetDeg", 0, "deg", "added to the heading");
    private double offsetDeg;

    public CompassTestSensor() {
        super(new SensorInfo("compass", "the heading and an offset", List.of(OFFSET), "one value, deg", "deg", false,
                SensorInfo.Display.VALUES));
    }

    @Override
    protected void configure(Attributes attributes) {
        offsetDeg = OFFSET.read(attributes);
    }

    @Override
    public SensorValues values() {
        return new SensorValues(1, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, "deg");
    }

    @Override
    public double[] generateSensorResponse(SensorContext context) {
        return new double[] {context.headingDeg() + offsetDeg};
    }
}
