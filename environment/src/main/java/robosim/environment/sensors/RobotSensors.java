package robosim.environment.sensors;

import java.util.Map;

/** Makes sensors from the environment file: {@code laser}, {@code heat}, {@code bump} or a class name. */
public final class RobotSensors {
    private static final Map<String, Class<? extends RobotSensor>> BUILT_IN = Map.of(
            "laser", LaserSensor.class, "heat", HeatSensor.class, "bump", BumpSensor.class);

    private RobotSensors() {
    }

    /**
     * A configured sensor of {@code type}. Anything wrong (unknown type, not a RobotSensor, a bad or
     * unknown attribute) is an IllegalArgumentException whose message says what. A class named in a file
     * is checked to be a {@link RobotSensor} before it is initialised: a class that is not one never runs
     * its static initialiser.
     */
    public static RobotSensor create(String type, Map<String, String> attributes) {
        Class<? extends RobotSensor> c = BUILT_IN.get(type);
        if (c == null) {
            try {
                c = Class.forName(type, false, RobotSensors.class.getClassLoader()).asSubclass(RobotSensor.class);
            } catch (ClassNotFoundException e) {
                throw new IllegalArgumentException("type \"" + type + "\" is neither laser, heat, bump nor a class on "
                        + "the class path");
            } catch (ClassCastException e) {
                throw new IllegalArgumentException("class " + type + " does not extend " + RobotSensor.class.getName());
            }
        }
        RobotSensor sensor;
        try {
            sensor = c.getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException e) {
            throw new IllegalArgumentException("class " + type + " needs a public no-argument constructor");
        }
        SensorParameters p = new SensorParameters(attributes);
        sensor.configure(p);
        if (!p.unread().isEmpty()) {
            throw new IllegalArgumentException("unknown attribute(s) " + p.unread() + " for a " + type + " sensor");
        }
        return sensor;
    }
}
