package robosim.devices;

import java.util.Map;

/**
 * One device a robot has, as an environment file's {@code <sensor>} or a robot type gives it: the name control code
 * asks for it by, whether it senses or acts, its kind (a registered sensor's or actuator's name, or a sensor class)
 * and its attributes. One name may be both a sensor and an actuator of a robot (its range-and-bearing device: {@code
 * rab} hears and sends).
 */
public record DeviceSpec(String name, boolean actuator, String kind, Map<String, String> attributes) {
    public DeviceSpec {
        attributes = Map.copyOf(attributes);
    }

    /** A sensor: what a file's {@code <sensor name= type= ...>} gives. */
    public DeviceSpec(String name, String kind, Map<String, String> attributes) {
        this(name, false, kind, attributes);
    }

    /** A sensor named after its kind, with attributes {@code name, value, name, value, ...}. */
    public static DeviceSpec sensor(String kind, String... attributes) {
        return new DeviceSpec(kind, false, kind, pairs(attributes));
    }

    /** An actuator named after its kind, with attributes {@code name, value, ...}. */
    public static DeviceSpec actuator(String kind, String... attributes) {
        return new DeviceSpec(kind, true, kind, pairs(attributes));
    }

    private static Map<String, String> pairs(String... attributes) {
        Map<String, String> a = new java.util.LinkedHashMap<>();
        for (int k = 0; k + 1 < attributes.length; k += 2) {
            a.put(attributes[k], attributes[k + 1]);
        }
        return a;
    }
}
