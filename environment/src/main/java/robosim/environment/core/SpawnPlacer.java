package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Point;
import robosim.protocol.ObstacleShape;

/**
 * Where a robot that joins a running world enters: the first free pose of its rule's spawn region (row by
 * row from the lower-left, centres {@link #GAP_MM} further apart than the robot is wide), or an any-time
 * robot's start pose, if free. Free means inside the arena, clear of every obstacle (JTS distance) and of
 * every robot in the world, held ones too (centre distance at least the two radii). Deterministic: the same
 * world gives the same pose.
 */
public final class SpawnPlacer {
    /** Room left between two robots that enter side by side, mm. */
    public static final double GAP_MM = 100;

    private final GeometryFactory jts = new GeometryFactory();
    private final List<Geometry> obstacles = new ArrayList<>();
    private final List<String> obstacleNames = new ArrayList<>();

    public SpawnPlacer(WorldSpec spec) {
        for (ObstacleShape o : spec.obstacles()) {
            obstacles.add(Obstacles.polygon(o));
            obstacleNames.add(o.name());
        }
    }

    /**
     * Where {@code rule}'s robot enters {@code map}'s world now: {x, y} mm, or null when nowhere is free.
     * {@code why} gets what takes an any-time robot's start pose.
     */
    public double[] place(JoinRule rule, EnvironmentMap map, StringBuilder why) {
        double r = rule.template().radiusMm();
        if (rule.spawn() == null) {
            String taken = taken(rule.template().xMm(), rule.template().yMm(), r, map);
            if (taken != null) {
                why.append(taken);
                return null;
            }
            return new double[] {rule.template().xMm(), rule.template().yMm()};
        }
        JoinRule.Spawn s = rule.spawn();
        double pitch = 2 * r + GAP_MM;
        for (double y = s.yMm() + r; y <= s.yMm() + s.heightMm() - r; y += pitch) {
            for (double x = s.xMm() + r; x <= s.xMm() + s.widthMm() - r; x += pitch) {
                if (taken(x, y, r, map) == null) {
                    return new double[] {x, y};
                }
            }
        }
        why.append("every pose in it is taken");
        return null;
    }

    /** What a disc of radius r at (x, y) would overlap, or null if nothing. */
    private String taken(double x, double y, double r, EnvironmentMap map) {
        for (int i = 0; i < map.robotCount(); i++) {
            if (!map.isGone(i) && Math.hypot(map.xMm(i) - x, map.yMm(i) - y) < r + map.properties(i).radiusMm()) {
                return "robot " + map.name(i) + " stands there";
            }
        }
        Point centre = jts.createPoint(new Coordinate(x, y));
        for (int o = 0; o < obstacles.size(); o++) {
            if (obstacles.get(o).distance(centre) < r) {
                return "obstacle " + obstacleNames.get(o) + " is there";
            }
        }
        return null;
    }
}
