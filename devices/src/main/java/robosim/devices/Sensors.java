package robosim.devices;

import robosim.protocol.RobotProperties;

import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.TreeMap;

/**
 * The sensors a world may give its robots: every {@link RobotSensor} registered for {@link ServiceLoader} on the class
 * path, by name, and any RobotSensor class named in a file. The file reader makes each robot's sensors here, and its
 * errors, {@code describe.sh sensors} and whoever shows a reading read the names and the {@link SensorInfo}s here.
 * Any thread.
 */
public final class Sensors {
    /** Each registered sensor's provider (a new instance a call), by name. */
    private static final Map<String, ServiceLoader.Provider<RobotSensor>> PROVIDERS = load();
    private static final List<SensorInfo> REGISTERED = PROVIDERS.values().stream().map(p -> p.get().info())
            .sorted(Comparator.comparing(SensorInfo::name)).toList();

    private Sensors() {
    }

    /** Every registered sensor, by name. */
    public static List<SensorInfo> all() {
        return REGISTERED;
    }

    /** The registered sensor named {@code name}, or null. */
    public static SensorInfo info(String name) {
        for (SensorInfo s : REGISTERED) {
            if (s.name().equals(name)) {
                return s;
            }
        }
        return null;
    }

    /**
     * The registered sensor a reading named {@code reading} of {@code values} values is most likely of, for whoever
     * sees readings without the file (a viewer, a recording): the one of that name (a file's sensor named after its
     * type, as by default), else the one named by a word of the reading's name, words being parted by anything but a
     * letter, case aside ({@code front-laser}, {@code Rear_Bump}; not {@code heatmap}, nor a class name such as
     * {@code com.example.HeatCamera}); null for none, for two kinds named ({@code sonar_laser}), or where the values
     * do not fit the kind (one that shows sides has as many values as it has sides).
     */
    public static SensorInfo kindOf(String reading, int values) {
        SensorInfo exact = info(reading);
        if (exact != null) {
            return fits(exact, values) ? exact : null;
        }
        SensorInfo found = null;
        for (String word : reading.split("[^\\p{L}]+")) {
            for (SensorInfo s : REGISTERED) {
                if (s.name().equalsIgnoreCase(word) && s != found) {
                    if (found != null) {
                        return null;
                    }
                    found = s;
                }
            }
        }
        return found != null && fits(found, values) ? found : null;
    }

    private static boolean fits(SensorInfo kind, int values) {
        return kind.display() != SensorInfo.Display.SIDES || values == SensorInfo.Display.SIDES_NAMED.size();
    }

    /**
     * How a viewer shows a reading named {@code reading} of {@code values} values: as the sensor it is most likely of
     * says ({@link #kindOf}); for none (a sensor of one's own), ranges when it has at least {@link #RANGES_FROM}
     * values, else the values.
     */
    public static SensorInfo.Display display(String reading, int values) {
        SensorInfo s = kindOf(reading, values);
        return s != null ? s.display() : values >= RANGES_FROM ? SensorInfo.Display.RANGES : SensorInfo.Display.VALUES;
    }

    /** The fewest values of a reading of an unknown sensor that a viewer draws as ranges. */
    public static final int RANGES_FROM = 9;

    /** The names of the sensors a file's {@code <sensor type="...">} may name (those the Environment computes). */
    public static String fileNames() {
        return String.join(", ", REGISTERED.stream().filter(s -> !s.geometry()).map(SensorInfo::name).toList());
    }

    /**
     * A configured sensor of {@code type}: a registered sensor's name, or a RobotSensor class name, mounted on
     * {@code robot} (null: not known). Anything wrong (an unknown type, a class that is not a RobotSensor, a bad or
     * unknown attribute) is an IllegalArgumentException whose message says what. A class named in a file is checked to
     * be a {@link RobotSensor} before it is initialised: a class that is not one never runs its static initialiser.
     */
    public static RobotSensor create(String type, Map<String, String> attributes, RobotProperties robot) {
        return created(type, attributes, robot);
    }

    /** As {@link #create(String, Map, RobotProperties)} on a body not known. */
    public static RobotSensor create(String type, Map<String, String> attributes) {
        return created(type, attributes, null);
    }

    private static RobotSensor created(String type, Map<String, String> attributes, RobotProperties robot) {
        RobotSensor sensor = registered(type);
        if (sensor == null) {
            sensor = ofClass(type);
        }
        Attributes a = new Attributes(attributes);
        sensor.configure(a);
        if (!a.unread().isEmpty()) {
            throw new IllegalArgumentException("unknown attribute(s) " + a.unread() + " for a " + type + " sensor "
                    + "(it takes: " + String.join(", ", sensor.info().attributes().stream().map(Attribute::name)
                    .toList()) + ")");
        }
        sensor.mount(robot);
        return sensor;
    }

    private static RobotSensor registered(String type) {
        ServiceLoader.Provider<RobotSensor> p = PROVIDERS.get(type);
        return p == null ? null : p.get();
    }

    private static RobotSensor ofClass(String type) {
        Class<? extends RobotSensor> c;
        try {
            c = Class.forName(type, false, Sensors.class.getClassLoader()).asSubclass(RobotSensor.class);
        } catch (ClassNotFoundException e) {
            throw new IllegalArgumentException("type \"" + type + "\" is neither " + fileNames()
                    + " nor a class on the class path");
        } catch (ClassCastException e) {
            throw new IllegalArgumentException("class " + type + " does not extend " + RobotSensor.class.getName());
        } catch (LinkageError e) {
            throw new IllegalArgumentException("class " + type + " could not be loaded: " + e);
        }
        try {
            return c.getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException e) {
            throw new IllegalArgumentException("class " + type + " needs a public no-argument constructor");
        } catch (LinkageError e) {
            throw new IllegalArgumentException("class " + type + " could not be loaded: " + e);
        }
    }

    private static Map<String, ServiceLoader.Provider<RobotSensor>> load() {
        Map<String, ServiceLoader.Provider<RobotSensor>> all = new TreeMap<>();
        ServiceLoader.load(RobotSensor.class, Sensors.class.getClassLoader()).stream().forEach(p -> {
            ServiceLoader.Provider<RobotSensor> was = all.put(p.get().info().name(), p);
            if (was != null) {
                throw new IllegalStateException("two sensors are named " + p.get().info().name() + ": "
                        + was.type().getName() + " and " + p.type().getName());
            }
        });
        return all;
    }
}
