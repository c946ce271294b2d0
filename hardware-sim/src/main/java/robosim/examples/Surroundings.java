package robosim.examples;

/**
 * What a robot's sonar says of its surroundings, as {@link Wander} and {@link Bounce} decide by it: the nearest range
 * of a sonar facing within 60 degrees of ahead, and the sums of the ranges to its left and to its right (the more
 * open side has the larger sum).
 *
 * @param aheadMm the nearest range ahead, mm (infinite: no sonar faces ahead)
 * @param leftMm the sum of the ranges of the sonars facing left (0 to 180 degrees, counter-clockwise), mm
 * @param rightMm the sum of the ranges of the sonars facing right, mm
 */
public record Surroundings(double aheadMm, double leftMm, double rightMm) {
    /** The surroundings sonars pointing at {@code anglesDeg} (degrees from ahead) read as {@code rangesMm}. */
    public static Surroundings of(double[] anglesDeg, double[] rangesMm) {
        double ahead = Double.POSITIVE_INFINITY;
        double left = 0;
        double right = 0;
        for (int s = 0; s < rangesMm.length; s++) {
            double a = normalise(anglesDeg[s]);
            if (Math.abs(a) <= 60) {
                ahead = Math.min(ahead, rangesMm[s]);
            }
            if (a > 0 && a < 180) {
                left += rangesMm[s];
            } else if (a < 0) {
                right += rangesMm[s];
            }
        }
        return new Surroundings(ahead, left, right);
    }

    /** {@code deg} in (-180, 180]. */
    static double normalise(double deg) {
        double a = deg % 360;
        if (a > 180) {
            a -= 360;
        } else if (a <= -180) {
            a += 360;
        }
        return a;
    }
}
