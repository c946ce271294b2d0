package robosim.examples;

/**
 * The sines, cosines, angles and lengths ARGoS's controllers take of their sensors' vectors, computed by arithmetic
 * alone (no call into a maths library, whose last bit differs between Java's intrinsics and the C library Python
 * uses), in an order of operations that Python's {@code robosim.portable} follows exactly: a Java controller and its
 * Python twin ({@code examples/python/}) give the same bits, and so the same pose log. Accurate to about 1e-12, far
 * beyond what any threshold of theirs asks.
 */
public final class PortableMath {
    /** Radians in a degree: Java's {@code Math.toRadians} factor, written out (Python's {@code math.radians} too). */
    public static final double RADIANS_PER_DEGREE = 0.017453292519943295;
    private static final double QUARTER_PI = 0.7853981633974483;
    private static final double HALF_PI = 1.5707963267948966;
    private static final double PI = 3.141592653589793;
    /** tan(pi / 8): above it, atan is taken of (z - 1) / (z + 1), a quarter pi on. */
    private static final double TAN_EIGHTH_PI = 0.41421356237309503;

    private PortableMath() {
    }

    /** The angle of (x, y) from +x, radians in [-pi, pi], as {@code Math.atan2(y, x)}; 0 for (0, 0). */
    public static double angle(double y, double x) {
        if (x == 0 && y == 0) {
            return 0;
        }
        double ax = Math.abs(x);
        double ay = Math.abs(y);
        boolean steep = ay > ax;
        double z = steep ? ax / ay : ay / ax;
        double base = 0;
        if (z > TAN_EIGHTH_PI) {
            z = (z - 1) / (z + 1);
            base = QUARTER_PI;
        }
        double z2 = z * z;
        double s = 0;
        for (int k = 25; k >= 1; k -= 2) {
            s = 1.0 / k - z2 * s;
        }
        double a = base + z * s;
        if (steep) {
            a = HALF_PI - a;
        }
        if (x < 0) {
            a = PI - a;
        }
        return y < 0 ? -a : a;
    }

    /** The length of (x, y), as {@code Math.hypot} (a square root is exact in both languages). */
    public static double length(double x, double y) {
        return Math.sqrt(x * x + y * y);
    }

    /** The sine of {@code a} radians. */
    public static double sin(double a) {
        return cos(a - HALF_PI);
    }

    /** The cosine of {@code a} radians. */
    public static double cos(double a) {
        double r = a - 2 * PI * Math.floor(a / (2 * PI) + 0.5); // (in [-pi, pi])
        boolean flip = r > HALF_PI || r < -HALF_PI;
        if (flip) {
            r = r > 0 ? PI - r : -PI - r;
        }
        double r2 = r * r;
        double s = 0;
        for (int k = 20; k >= 2; k -= 2) {
            s = 1 - r2 / (k * (k - 1)) * s;
        }
        return flip ? -s : s;
    }

    /** {@code base} to the whole power {@code n} >= 0 by multiplication. */
    public static double power(double base, int n) {
        double p = 1;
        for (int k = 0; k < n; k++) {
            p *= base;
        }
        return p;
    }
}
