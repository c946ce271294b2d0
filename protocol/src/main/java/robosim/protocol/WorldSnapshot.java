package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * Environment -> viewer, once, right after {@link ViewerHello}: the whole world as it stands after
 * {@code step} (-1 before the first step): time step, arena, obstacles and every robot's name and
 * properties (type, radius, sonar layout) and pose (mm, degrees). {@link PoseUpdate}s follow, with
 * robots in the same order.
 */
public final class WorldSnapshot implements java.io.Externalizable {
    /**
     * Fixed at the value the JDK computed for the class recordings of version 4 hold, so that they read; what each
     * version writes is told apart by the recording's version ({@link RecordingFormat}), not by this.
     */
    private static final long serialVersionUID = -3996007456098852125L;

    private long step;
    private long timeStepMs;
    private Arena arena;
    private List<ObstacleShape> obstacles = List.of();
    private List<String> robotNames = List.of();
    private List<RobotProperties> robots = List.of();
    private PoseUpdate poses = new PoseUpdate();
    private Scenery scenery = Scenery.NONE;

    public WorldSnapshot() {
    }

    /** A world without floor, lights or objects. */
    public WorldSnapshot(long timeStepMs, Arena arena, List<ObstacleShape> obstacles, List<String> robotNames,
            List<RobotProperties> robots, PoseUpdate poses) {
        this(timeStepMs, arena, obstacles, robotNames, robots, poses, Scenery.NONE);
    }

    /**
     * @param scenery the floor, the lights and the objects (at their start poses; where they stand at {@code step} is
     *     in {@code poses})
     */
    public WorldSnapshot(long timeStepMs, Arena arena, List<ObstacleShape> obstacles, List<String> robotNames,
            List<RobotProperties> robots, PoseUpdate poses, Scenery scenery) {
        this.step = poses.step();
        this.timeStepMs = timeStepMs;
        this.arena = arena;
        this.obstacles = List.copyOf(obstacles);
        this.robotNames = List.copyOf(robotNames);
        this.robots = List.copyOf(robots);
        this.poses = poses;
        this.scenery = scenery;
        if (robotNames.size() != robots.size() || robotNames.size() != poses.count()) {
            throw new IllegalArgumentException("snapshot robot fields differ in length");
        }
        if (poses.objectCount() != 0 && poses.objectCount() != scenery.objects().size()) {
            throw new IllegalArgumentException("snapshot has " + scenery.objects().size() + " objects but "
                    + poses.objectCount() + " object poses");
        }
    }

    public long step() {
        return step;
    }

    public long timeStepMs() {
        return timeStepMs;
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

    /** Each robot's properties (type, radius, sonar layout), in {@link #robotNames()} order. */
    public List<RobotProperties> robots() {
        return robots;
    }

    public double radiusMm(int robot) {
        return robots.get(robot).radiusMm();
    }

    /** The floor, the lights, and the objects (at their start poses). */
    public Scenery scenery() {
        return scenery;
    }

    /** The robots' poses at {@link #step()}. */
    public PoseUpdate poses() {
        return poses;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeLong(timeStepMs);
        arena.write(out);
        Wire.writeObstacles(out, obstacles);
        out.writeInt(robotNames.size());
        for (int i = 0; i < robotNames.size(); i++) {
            out.writeUTF(robotNames.get(i));
            robots.get(i).write(out);
        }
        poses.writeExternal(out);
        scenery.write(out);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        timeStepMs = in.readLong();
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
        poses = new PoseUpdate();
        poses.readExternal(in);
        if (poses.count() != n) {
            throw new ProtocolException("snapshot has " + n + " robots but " + poses.count() + " poses");
        }
        scenery = RecordingVersion.withScene(in) ? Scenery.read(in) : Scenery.NONE;
        if (poses.objectCount() != 0 && poses.objectCount() != scenery.objects().size()) {
            throw new ProtocolException("snapshot has " + scenery.objects().size() + " objects but "
                    + poses.objectCount() + " object poses");
        }
    }
}
