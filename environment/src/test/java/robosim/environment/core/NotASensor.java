package robosim.environment.core;

/**
 * Named as a sensor type in a test: not a {@code RobotSensor}, with a static initialiser that must never
 * run (it says so in {@link Initialised}, which can be read without initialising this class).
 */
public final class NotASensor {
    static {
        Initialised.notASensor = true;
    }

    private NotASensor() {
    }

    /** What ran its static initialiser. */
    static final class Initialised {
        static volatile boolean notASensor;

        private Initialised() {
        }
    }
}
