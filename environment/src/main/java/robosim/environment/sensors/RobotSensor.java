package robosim.environment.sensors;

/**
 * A sensor the Environment answers. To add one, write one class that extends this, has a public
 * no-argument constructor and implements {@link #generateSensorResponse}, and name it in the
 * environment file: {@code <sensor name="gas" type="com.example.GasSensor" anyAttribute="..."/>}
 * inside a {@code <robot>}. No other file changes. Its attributes reach {@link #configure}; an
 * attribute it does not read is reported as a mistake in the file.
 *
 * <p>One instance per robot and sensor; called on the step's thread, after all moves of the step.
 * Gaussian noise ({@code noise="sigma"}, in the sensor's own units) is added by the Environment from
 * the world's seeded generator, so sensors stay deterministic.
 */
public abstract class RobotSensor {
    /** Reads this sensor's attributes from the environment file; the default takes none. */
    protected void configure(SensorParameters parameters) {
    }

    /** This step's reading for the robot the context is aimed at. Units and order are the sensor's own. */
    public abstract double[] generateSensorResponse(SensorContext context);
}
