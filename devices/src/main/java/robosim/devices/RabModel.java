package robosim.devices;

/**
 * A range-and-bearing device as a robot type carries it (ARGoS's numbers): how far its messages carry, how many bytes
 * one holds, how high over the floor it sits, whether a message needs a clear line between the two devices, and
 * whether the receiver senses the bearing. The sensor ({@link RabSensor}) and the actuator ({@link RabActuator}) of
 * one robot are of one model.
 */
public enum RabModel {
    /** The foot-bot's: 3 m, 10 bytes, 100 mm up, line of sight, bearing. */
    FOOT_BOT("foot-bot", 3000, 10, 100, true, true),
    /** The e-puck's: 0.8 m, 2 bytes, 86 mm up, line of sight, bearing. */
    E_PUCK("e-puck", 800, 2, 86, true, true),
    /** The kilobot's infrared messages: 0.1 m, 9 bytes, 35 mm up, no occlusion, distance only. */
    KILOBOT("kilobot", 100, 9, 35, false, false);

    private final String word;
    private final double rangeMm;
    private final int bytes;
    private final double heightMm;
    private final boolean occluded;
    private final boolean bearing;

    RabModel(String word, double rangeMm, int bytes, double heightMm, boolean occluded, boolean bearing) {
        this.word = word;
        this.rangeMm = rangeMm;
        this.bytes = bytes;
        this.heightMm = heightMm;
        this.occluded = occluded;
        this.bearing = bearing;
    }

    /** The model a file's {@code model} attribute names. */
    static RabModel of(String word) {
        for (RabModel m : values()) {
            if (m.word.equals(word)) {
                return m;
            }
        }
        throw new IllegalArgumentException("no range-and-bearing model " + word);
    }

    /** The {@code model} attribute both devices take. */
    static final Attribute ATTRIBUTE = Attribute.choice("model", "whose device: range, message size, height, "
            + "occlusion, bearing", "foot-bot", "e-puck", "kilobot");

    /** Its name in a file's {@code model} attribute. */
    public String word() {
        return word;
    }

    public double rangeMm() {
        return rangeMm;
    }

    public int bytes() {
        return bytes;
    }

    public double heightMm() {
        return heightMm;
    }

    /** True when a message needs a line between the devices clear of anything taller than it. */
    public boolean occluded() {
        return occluded;
    }

    /** True when the receiver senses the sender's bearing. */
    public boolean bearing() {
        return bearing;
    }
}
