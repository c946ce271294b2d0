package robosim.environment.core;

import robosim.protocol.ObstacleShape;

/**
 * The tag ACTION: a robot tags the nearest other robot, or obstacle marked taggable, whose nearest
 * point lies within the tag range of its rim and within {@link WorldSpec#TAG_HALF_ANGLE_DEG} of its
 * heading. Robots win ties over obstacles, and earlier ones in world order over later ones.
 */
final class Tags {
    private Tags() {
    }

    /** The name of what robot i tags now, or "" for nothing. */
    static String nearest(EnvironmentMap map, int i, double rangeMm) {
        double cx = map.xMm(i);
        double cy = map.yMm(i);
        double rim = map.radiusMm(i);
        double best = Double.POSITIVE_INFINITY;
        String hit = "";
        for (int j = 0; j < map.robotCount(); j++) {
            if (j == i || map.isGone(j)) {
                continue;
            }
            double d = Math.hypot(map.xMm(j) - cx, map.yMm(j) - cy) - rim - map.radiusMm(j);
            if (d <= rangeMm && d < best && inFront(map.headingDeg(i), map.xMm(j) - cx, map.yMm(j) - cy)) {
                best = d;
                hit = map.name(j);
            }
        }
        for (ObstacleShape o : map.spec().obstacles()) {
            if (!map.spec().taggable().contains(o.name())) {
                continue;
            }
            int n = o.vertexCount();
            for (int v = 0; v < n; v++) {
                int w = (v + 1) % n;
                double ex = o.x(w) - o.x(v);
                double ey = o.y(w) - o.y(v);
                double len2 = ex * ex + ey * ey;
                double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((cx - o.x(v)) * ex + (cy - o.y(v)) * ey) / len2));
                double px = o.x(v) + t * ex - cx;
                double py = o.y(v) + t * ey - cy;
                double d = Math.hypot(px, py) - rim;
                if (d <= rangeMm && d < best && inFront(map.headingDeg(i), px, py)) {
                    best = d;
                    hit = o.name();
                }
            }
        }
        return hit;
    }

    private static boolean inFront(double headingDeg, double dx, double dy) {
        double rel = (Math.toDegrees(Math.atan2(dy, dx)) - headingDeg) % 360;
        if (rel > 180) {
            rel -= 360;
        } else if (rel <= -180) {
            rel += 360;
        }
        return Math.abs(rel) <= WorldSpec.TAG_HALF_ANGLE_DEG;
    }
}
