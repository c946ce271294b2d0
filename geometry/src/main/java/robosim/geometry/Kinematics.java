package robosim.geometry;

/**
 * The one motion model, used by Geometry to resolve moves and by the Environment to apply the
 * distances Geometry returns, so both compute identical poses bit for bit. A step turns first,
 * then moves along the new heading. Headings are degrees in [0, 360), counter-clockwise from +x.
 */
public final class Kinematics {
    private Kinematics() {
    }

    public static double turn(double headingDeg, double turnDeg) {
        double h = (headingDeg + turnDeg) % 360.0;
        return h < 0 ? h + 360.0 : h;
    }

    public static double dx(double headingDeg, double movedMm) {
        return movedMm * Math.cos(Math.toRadians(headingDeg));
    }

    public static double dy(double headingDeg, double movedMm) {
        return movedMm * Math.sin(Math.toRadians(headingDeg));
    }
}
