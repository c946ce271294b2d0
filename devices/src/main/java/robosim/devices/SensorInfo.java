package robosim.devices;

import java.util.List;

/**
 * What a kind of sensor is, declared once, in its class ({@link RobotSensor}): its name (what an environment file's
 * {@code <sensor type="...">} says), a line on what it senses, the attributes the file may give it, what its values
 * are (their order and unit, as a sentence), their unit, whether the Geometry process computes it (it casts its rays
 * there, as sonar does) or the Environment, and how a viewer shows a reading of it. The file reader, the error
 * messages, {@code describe.sh sensors}, the learners' observation spaces and the viewers' robot panels read it.
 */
public record SensorInfo(String name, String summary, List<Attribute> attributes, String values, String unit,
        boolean geometry, Display display) {
    /** How a viewer's robot panel shows a reading of the sensor. */
    public enum Display {
        /** Ranges along beams around the heading, one degree apart, centred on it, drawn as points. */
        RANGES,
        /** One value a side, {@link #SIDES_NAMED}, each lit when not 0. */
        SIDES,
        /** Numbers, as they are. */
        VALUES;

        /** The sides of a {@link #SIDES} reading, in its order. */
        public static final java.util.List<String> SIDES_NAMED = java.util.List.of("front", "left", "back", "right");
    }

    public SensorInfo {
        if (name == null || !name.matches("[a-z][a-z0-9_]{0,31}")) {
            throw new IllegalArgumentException("a sensor's name is 1 to 32 lower-case letters, digits and _, got "
                    + name);
        }
        attributes = List.copyOf(attributes);
    }

    /** Its attribute named {@code attribute}, or null. */
    public Attribute attribute(String attribute) {
        for (Attribute a : attributes) {
            if (a.name().equals(attribute)) {
                return a;
            }
        }
        return null;
    }
}
