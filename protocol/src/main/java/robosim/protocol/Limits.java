package robosim.protocol;

/**
 * Bounds on every count a message reads from the wire, checked before anything is allocated.
 * A value outside its bound raises a {@link ProtocolException} that names the field and the value.
 */
public final class Limits {
    /** Robots in one world (and entries in one per-step batch). */
    public static final int MAX_ROBOTS = 100_000;
    /**
     * Robots on one shared connection (one robot process's): with each hello under {@link #MAX_HELLO_BYTES},
     * a stranger's handshake may take at most 32 MiB.
     */
    public static final int MAX_ROBOTS_PER_CONNECTION = 2048;
    /** Static obstacles in one world. */
    public static final int MAX_OBSTACLES = 100_000;
    /** Vertices of one obstacle polygon. */
    public static final int MAX_VERTICES = 10_000;
    /** Objects (boxes, cylinders) in one world. */
    public static final int MAX_OBJECTS = 100_000;
    /** Lights in one world. */
    public static final int MAX_LIGHTS = 10_000;
    /** Painted regions of one floor. */
    public static final int MAX_FLOOR_REGIONS = 10_000;
    /** Pixels of a floor's image (1024 x 1024): what every viewer is sent once. */
    public static final int MAX_FLOOR_PIXELS = 1 << 20;
    /** Rays of one robot's proximity sensors. */
    public static final int MAX_RAYS = 64;
    /** LEDs on one robot. */
    public static final int MAX_LEDS = 64;
    /** Sonar transducers on one robot. */
    public static final int MAX_SONARS = 64;
    /** Tags listed in one pose update. */
    public static final int MAX_TAGS = 1_000_000;
    /** Plug-in sensors on one robot. */
    public static final int MAX_SENSORS = 64;
    /** Parameters one robot is given (an environment file's {@code <param>}s, the world's and its own together). */
    public static final int MAX_PARAMETERS = 256;
    /** The longest parameter value, bytes (modified UTF-8), and name, characters. */
    public static final int MAX_PARAMETER_BYTES = 4096;
    public static final int MAX_PARAMETER_NAME_CHARS = 64;
    /** Values in one sensor reading (a laser scan of 0.1-degree steps all round fits). */
    public static final int MAX_SENSOR_VALUES = 4096;
    /** Messages one robot may send, or receive, in one step. */
    public static final int MAX_MESSAGES_PER_STEP = 10_000;
    /** Sonar ranges in one geometry response. */
    public static final int MAX_RANGES = MAX_ROBOTS * 16;
    /** Bytes a string may take on the wire ({@code writeUTF}'s own limit). */
    public static final int MAX_UTF_BYTES = 65_535;
    /** Bytes one message may occupy on the wire (checked by {@link ObjectConnection}). */
    public static final int MAX_MESSAGE_BYTES = 64 * 1024 * 1024;
    /**
     * Bytes a client may send before its hello is accepted (the stream header and the hello itself): a
     * stranger gets this much of the Environment's attention, not {@link #MAX_MESSAGE_BYTES}. The largest
     * legitimate hello, a robot with 64 sonars and 64 plug-in sensors, is under 8 KiB.
     */
    public static final int MAX_HELLO_BYTES = 16 * 1024;

    private Limits() {
    }

    /** Bytes {@code s} takes as modified UTF-8 ({@code writeUTF}), without allocating. */
    public static int utfLength(String s) {
        int bytes = 0;
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            bytes += c >= 1 && c < 0x80 ? 1 : c < 0x800 ? 2 : 3;
        }
        return bytes;
    }

    /** Returns {@code value} if it lies in [0, max], else throws naming {@code field}. */
    public static int checkCount(String field, int value, int max) throws ProtocolException {
        if (value < 0 || value > max) {
            throw new ProtocolException(field + " must be in [0, " + max + "], got " + value);
        }
        return value;
    }
}
