package robosim.environment.sensors;

/** A plug-in sensor that always fails: the run must go on. */
public final class FailingTestSensor extends RobotSensor {
    @Override
    public double[] generateSensorResponse(SensorContext context) {
        throw new IllegalStateException("out of order");
    }
}
