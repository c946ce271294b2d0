package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * Environment -> Geometry, once, in answer to {@link GeometryHello}: the static world (arena and
 * obstacles, mm), every robot's name and properties and every object's shape and physics, in world order (the order
 * every later per-step batch uses).
 */
public final class GeometryWorld implements java.io.Externalizable {
    private Arena arena;
    private List<ObstacleShape> obstacles = List.of();
    private List<String> robotNames = List.of();
    private List<RobotProperties> robots = List.of();
    private List<WorldObject> objects = List.of();

    public GeometryWorld() {
    }

    /** A world without objects. */
    public GeometryWorld(Arena arena, List<ObstacleShape> obstacles, List<String> robotNames,
            List<RobotProperties> robots) {
        this(arena, obstacles, robotNames, robots, List.of());
    }

    /** @param objects the world's objects, in world order (their poses come with each step) */
    public GeometryWorld(Arena arena, List<ObstacleShape> obstacles, List<String> robotNames,
            List<RobotProperties> robots, List<WorldObject> objects) {
        if (robotNames.size() != robots.size()) {
            throw new IllegalArgumentException("robot names and properties differ in length: " + robotNames.size()
                    + " vs " + robots.size());
        }
        this.arena = arena;
        this.obstacles = List.copyOf(obstacles);
        this.robotNames = List.copyOf(robotNames);
        this.robots = List.copyOf(robots);
        this.objects = List.copyOf(objects);
    }

    /** The world's objects, in world order (the order of every step's object poses). */
    public List<WorldObject> objects() {
        return objects;
    }

    public Arena arena() {
        return arena;
    }

    public List<ObstacleShape> obstacles() {
        return obstacles;
    }

    public List<String> robotNames() {
        return robotNames;
    }

    public List<RobotProperties> robots() {
        return robots;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        arena.write(out);
        Wire.writeObstacles(out, obstacles);
        out.writeInt(robots.size());
        for (int i = 0; i < robots.size(); i++) {
            out.writeUTF(robotNames.get(i));
            robots.get(i).write(out);
        }
        Scenery.writeObjects(out, objects);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        arena = Arena.read(in);
        obstacles = Wire.readObstacles(in);
        int n = Limits.checkCount("robot count", in.readInt(), Limits.MAX_ROBOTS);
        List<String> names = new ArrayList<>(n);
        List<RobotProperties> props = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            names.add(in.readUTF());
            props.add(RobotProperties.read(in));
        }
        robotNames = List.copyOf(names);
        robots = List.copyOf(props);
        objects = Scenery.readObjects(in);
    }
}
