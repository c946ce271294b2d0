package robosim.geometry;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.ItemVisitor;
import org.locationtech.jts.index.strtree.STRtree;
import robosim.protocol.Arena;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.ObstacleShape;

/**
 * The walls that never move: the arena boundary and every obstacle's edges, in one STRtree built
 * once. Immutable after construction; queries may run on any one thread at a time per visitor.
 */
public final class StaticWorld {
    private final Arena arena;
    private final List<ObstacleShape> obstacles;
    private final STRtree index = new STRtree();
    /**
     * The obstacles' edges alone, and the box around them all (null without obstacles): what a line of sight asks of,
     * the arena's edges never blocking one (a crowd's cameras ask thousands a step).
     */
    private final STRtree obstacleIndex = new STRtree();
    private final Envelope obstacleBounds;
    private final int segmentCount;

    public StaticWorld(Arena arena, List<ObstacleShape> obstacles) {
        this.arena = arena;
        this.obstacles = List.copyOf(obstacles);
        List<Segment> segments = new ArrayList<>();
        double x0 = arena.minXMm();
        double y0 = arena.minYMm();
        double x1 = arena.maxXMm();
        double y1 = arena.maxYMm();
        byte a = GeometryStepResponse.CONTACT_ARENA;
        segments.add(new Segment(x0, y0, x1, y0, a, 0));
        segments.add(new Segment(x1, y0, x1, y1, a, 0));
        segments.add(new Segment(x1, y1, x0, y1, a, 0));
        segments.add(new Segment(x0, y1, x0, y0, a, 0));
        for (int o = 0; o < this.obstacles.size(); o++) {
            ObstacleShape shape = this.obstacles.get(o);
            int n = shape.vertexCount();
            for (int v = 0; v < n; v++) {
                int w = (v + 1) % n;
                segments.add(new Segment(shape.x(v), shape.y(v), shape.x(w), shape.y(w),
                        GeometryStepResponse.CONTACT_OBSTACLE, o));
            }
        }
        Envelope bounds = null;
        for (Segment s : segments) {
            Envelope e = new Envelope(s.ax, s.bx, s.ay, s.by);
            index.insert(e, s);
            if (s.ownerKind == GeometryStepResponse.CONTACT_OBSTACLE) {
                obstacleIndex.insert(e, s);
                if (bounds == null) {
                    bounds = new Envelope(e);
                } else {
                    bounds.expandToInclude(e);
                }
            }
        }
        index.build();
        obstacleIndex.build();
        obstacleBounds = bounds;
        segmentCount = segments.size();
    }

    public Arena arena() {
        return arena;
    }

    public List<ObstacleShape> obstacles() {
        return obstacles;
    }

    public int segmentCount() {
        return segmentCount;
    }

    /** Visits every segment whose envelope meets the given envelope (a cheap pre-filter). */
    void query(Envelope area, ItemVisitor visitor) {
        index.query(area, visitor);
    }

    /** Visits every obstacle's segment (not the arena's) whose envelope meets the given envelope. */
    void queryObstacles(Envelope area, ItemVisitor visitor) {
        if (obstacleBounds != null && obstacleBounds.intersects(area)) {
            obstacleIndex.query(area, visitor);
        }
    }
}
