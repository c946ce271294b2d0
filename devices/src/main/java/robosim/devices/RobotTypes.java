package robosim.devices;

import java.util.Map;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.TreeMap;
import robosim.protocol.RobotProperties;

/**
 * The robot types every RoboSim process knows by name: every {@link RobotType} registered for {@link ServiceLoader} on
 * the class path; and a RobotType class named by its class name. An environment file names one per robot; the
 * Hardware Simulator sends its properties in its handshake, and the Environment refuses a robot whose type differs
 * from the file's. Any thread.
 */
public final class RobotTypes {
    private static final Map<String, RobotType> KNOWN = load();

    private RobotTypes() {
    }

    /** The registered type named {@code name}, or null. */
    public static RobotType known(String name) {
        return KNOWN.get(name);
    }

    /** The properties of the registered type named {@code name}, or null. */
    public static RobotProperties properties(String name) {
        RobotType t = KNOWN.get(name);
        return t == null ? null : t.properties();
    }

    /** The registered types' names, in order. */
    public static Set<String> names() {
        return KNOWN.keySet();
    }

    /** Every registered type, by name. */
    public static java.util.Collection<RobotType> all() {
        return KNOWN.values();
    }

    /**
     * The type {@code name} names: a registered type, or the fully qualified name of a RobotType class with a public
     * no-argument constructor.
     *
     * @throws IllegalArgumentException naming the registered types, for a name that is neither
     */
    public static RobotType byName(String name) {
        RobotType t = KNOWN.get(name);
        if (t != null) {
            return t;
        }
        try { // (a class that is not a RobotType is not initialised: its static code never runs)
            return Class.forName(name, false, RobotTypes.class.getClassLoader()).asSubclass(RobotType.class)
                    .getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException | ClassCastException | LinkageError e) {
            throw new IllegalArgumentException("robot type \"" + name + "\" is neither " + String.join(", ", names())
                    + " nor a RobotType class on the class path");
        }
    }

    private static Map<String, RobotType> load() {
        Map<String, RobotType> all = new TreeMap<>();
        for (RobotType t : ServiceLoader.load(RobotType.class, RobotTypes.class.getClassLoader())) {
            RobotType was = all.put(t.name(), t);
            if (was != null) {
                throw new IllegalStateException("two robot types are named " + t.name() + ": "
                        + was.getClass().getName() + " and " + t.getClass().getName());
            }
        }
        return java.util.Collections.unmodifiableMap(all);
    }
}
