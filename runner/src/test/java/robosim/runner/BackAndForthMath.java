package robosim.runner;

/**
 * The pose of a BackAndForth robot after step k, worked out by hand: with a 500 ms step, 500 mm/s
 * and 90 deg/s, one cycle is 40 steps of +250 mm, 4 steps of +45 deg, 40 steps of -250 mm (heading
 * 180) and 4 more turns: 88 steps, back at the start.
 */
final class BackAndForthMath {
    private BackAndForthMath() {
    }

    /** {x offset mm, heading deg} after steps 0..k (k + 1 steps). */
    static double[] after(long k) {
        long done = k + 1;
        long c = done % 88;
        if (c <= 40) {
            return new double[] {250.0 * c, 0};
        }
        if (c <= 44) {
            return new double[] {10_000, 45.0 * (c - 40)};
        }
        if (c <= 84) {
            return new double[] {10_000 - 250.0 * (c - 44), 180};
        }
        return new double[] {0, (180 + 45.0 * (c - 84)) % 360};
    }
}
