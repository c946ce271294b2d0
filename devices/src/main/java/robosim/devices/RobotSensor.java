package robosim.devices;

import robosim.protocol.RobotProperties;

/**
 * A kind of sensor: one class, which declares what it is ({@link SensorInfo}: its name, its file attributes, its
 * values, whether the Geometry process computes it), reads its attributes ({@link #configure}), says the shape of its
 * values ({@link #values}) and computes them, its noise included, so they stay in their range
 * ({@link #generateSensorResponse}, the report's name). A built-in sensor is registered for
 * {@link java.util.ServiceLoader} ({@code @AutoService(RobotSensor.class)}) and named in a file by its name
 * ({@code <sensor type="laser"/>}); a sensor of one's own may be that too (its jar on the class path), or be named by
 * its class ({@code type="com.example.GasSensor"}). Either way no other file changes: the file reader, its errors,
 * {@code describe.sh sensors}, the learners' observation spaces and the viewers read {@link Sensors}.
 *
 * <p>Needs a public no-argument constructor. One instance per robot and sensor; called on the thread that steps
 * the world, after all moves of the step.
 */
public abstract class RobotSensor {
    private final SensorInfo info;

    protected RobotSensor(SensorInfo info) {
        this.info = info;
    }

    /** What kind of sensor it is. */
    public final SensorInfo info() {
        return info;
    }

    /**
     * Reads its attributes from the environment file (each declared in its {@link SensorInfo}, read with
     * {@link Attribute#read}); an attribute it does not read is reported as a mistake in the file. The default takes
     * none.
     */
    protected void configure(Attributes attributes) {
    }

    /**
     * Takes the body it is mounted on ({@code robot}: its radius, height, rays), after {@link #configure}; null when
     * it is not known (a robot type of one's own, named by its class, before it says hello): then the sensor assumes
     * a body as its attributes or its defaults say. The default ignores it.
     */
    protected void mount(RobotProperties robot) {
    }

    /** The values it gives each step, as configured: how many, their range, their unit. */
    public abstract SensorValues values();

    /**
     * This step's reading for the robot the context is aimed at, noise included, each value in the range
     * {@link #values} says. Units and order are its {@link SensorInfo#values()}.
     */
    public abstract double[] generateSensorResponse(SensorContext context);

    /**
     * {@code value} with Gaussian noise of deviation {@code sigma} (none at 0: no number is drawn), held to
     * [{@code low}, {@code high}].
     */
    protected static double noisy(double value, double sigma, SensorContext context, double low, double high) {
        double v = sigma > 0 ? value + sigma * context.gaussian() : value;
        return Math.max(low, Math.min(high, v));
    }
}
