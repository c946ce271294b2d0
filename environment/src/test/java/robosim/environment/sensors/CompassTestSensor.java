package robosim.environment.sensors;

/** A plug-in sensor that exists only in the tests: heading plus a configured offset. */
public final class CompassTestSensor extends RobotSensor {
    private double offsetDeg;

    @Override
    protected void configure(SensorParameters parameters) {
        offsetDeg = parameters.number("offsetDeg", 0);
    }

    @Override
    public double[] generateSensorResponse(SensorContext context) {
        return new double[] {context.headingDeg() + offsetDeg};
    }
}
