package robosim.environment.core;

import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.Polygon;
import robosim.protocol.ObstacleShape;

/** An obstacle as a JTS polygon, for the checks that need one (the file's, where a robot may enter). */
public final class Obstacles {
    private static final GeometryFactory JTS = new GeometryFactory();

    private Obstacles() {
    }

    /** {@code shape}'s outline as a closed JTS polygon (mm). */
    public static Polygon polygon(ObstacleShape shape) {
        Coordinate[] ring = new Coordinate[shape.vertexCount() + 1];
        for (int v = 0; v < shape.vertexCount(); v++) {
            ring[v] = new Coordinate(shape.x(v), shape.y(v));
        }
        ring[shape.vertexCount()] = ring[0];
        return JTS.createPolygon(ring);
    }
}
