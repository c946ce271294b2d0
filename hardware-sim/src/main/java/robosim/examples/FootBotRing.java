package robosim.examples;

/**
 * A foot-bot's rings of 24 proximity and 24 light sensors, as ARGoS's controllers read them: each reading a vector
 * along its sensor's direction (7.5 degrees, then every 15), summed. Directions by {@link PortableMath}, so that the
 * Python twins ({@code examples/python/argos_ring.py}) sum the same bits.
 */
public final class FootBotRing {
    private static final double ANGLE0_DEG = 7.5;
    private static final double STEP_DEG = 15;
    private static final double[] COS = new double[24];
    private static final double[] SIN = new double[24];

    static {
        for (int k = 0; k < 24; k++) {
            COS[k] = PortableMath.cos(PortableMath.RADIANS_PER_DEGREE * (ANGLE0_DEG + k * STEP_DEG));
            SIN[k] = PortableMath.sin(PortableMath.RADIANS_PER_DEGREE * (ANGLE0_DEG + k * STEP_DEG));
        }
    }

    private FootBotRing() {
    }

    /** The sum of {@code readings} (24, in ARGoS's order) as vectors along their sensors: {x ahead, y left}. */
    public static double[] sum(double[] readings) {
        double x = 0;
        double y = 0;
        for (int k = 0; k < readings.length; k++) {
            x += readings[k] * COS[k];
            y += readings[k] * SIN[k];
        }
        return new double[] {x, y};
    }
}
