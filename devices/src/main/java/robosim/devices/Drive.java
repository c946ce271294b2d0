package robosim.devices;

/**
 * How a velocity becomes a step's motion, in one place for every part that turns one into the other: the Hardware
 * Simulator cutting a call into steps, the learning host applying an action, the Environment holding a request to a
 * robot's limits. A step is {@code stepMs} of robot time; a rate held for it covers {@code rate * stepMs / 1000}.
 */
public final class Drive {
    private Drive() {
    }

    /** The seconds of robot time one step of {@code stepMs} takes. */
    public static double seconds(long stepMs) {
        return stepMs / 1000.0;
    }

    /** What a rate (mm/s, deg/s) covers in one step of {@code stepSeconds}: mm, degrees. */
    public static double perStep(double ratePerS, double stepSeconds) {
        return ratePerS * stepSeconds;
    }

    /**
     * This step's piece of a move or turn of which {@code remaining} is left, at {@code ratePerS}: all of it, or what the
     * rate covers in the step, in its direction.
     */
    public static double piece(double remaining, double ratePerS, double stepSeconds) {
        return Math.copySign(Math.min(Math.abs(remaining), perStep(ratePerS, stepSeconds)), remaining);
    }

    /**
     * One step of a differential drive with its wheels at {@code leftMmPerS} and {@code rightMmPerS}, {@code wheelBaseMm}
     * apart: the turn, degrees (it turns at {@code (right - left) / wheelBase} radians a second), and the move after
     * it, mm ({@code (left + right) / 2} a second), as a step turns and then moves.
     */
    public static double[] wheels(double leftMmPerS, double rightMmPerS, double wheelBaseMm, double stepSeconds) {
        return new double[] {Math.toDegrees((rightMmPerS - leftMmPerS) / wheelBaseMm) * stepSeconds,
            (leftMmPerS + rightMmPerS) / 2 * stepSeconds};
    }
}
