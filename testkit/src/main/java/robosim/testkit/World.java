package robosim.testkit;

import java.util.ArrayList;
import java.util.List;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;

/**
 * A world built in code, in the units of an environment file (metres and degrees): a rectangular arena with
 * its corner at the origin, rectangular obstacles and robots. For more (sensors, heat, tags, joins) write an
 * environment file ({@code test-envs/README.md}) and use {@link Simulation#of(java.nio.file.Path)}.
 */
public final class World {
    private final double widthM;
    private final double heightM;
    private long timeStepMs = 100;
    private long seed = 1;
    private double commRangeM;
    private final List<ObstacleShape> obstacles = new ArrayList<>();
    private final List<WorldSpec.RobotSpec> robots = new ArrayList<>();

    private World(double widthM, double heightM) {
        this.widthM = widthM;
        this.heightM = heightM;
    }

    /** An empty arena {@code widthM} x {@code heightM} metres, 100 ms steps, seed 1, messages carried everywhere. */
    public static World arena(double widthM, double heightM) {
        return new World(widthM, heightM);
    }

    public World timeStepMs(long ms) {
        timeStepMs = ms;
        return this;
    }

    /** The seed of the sensors' noise. */
    public World seed(long s) {
        seed = s;
        return this;
    }

    /** How far a message carries, centre to centre, m (0: everywhere). */
    public World commRangeM(double m) {
        commRangeM = m;
        return this;
    }

    /** A rectangular obstacle with its lower left corner at ({@code x}, {@code y}), m. */
    public World obstacle(String name, double x, double y, double width, double height) {
        obstacles.add(ObstacleShape.rectangle(name, x * 1000, y * 1000, width * 1000, height * 1000));
        return this;
    }

    /**
     * A robot of {@code type} ({@code ArRobot}, {@code Scout}) at ({@code x}, {@code y}) m, heading {@code heading}
     * degrees; its control code is given to the {@link Simulation.Builder}.
     */
    public World robot(String name, String type, double x, double y, double heading) {
        robots.add(new WorldSpec.RobotSpec(name, type, "", x * 1000, y * 1000, heading));
        return this;
    }

    /** The world as the Environment takes it. */
    WorldSpec spec() {
        return new WorldSpec("a world built in code", "world", timeStepMs, seed,
                new Arena(0, 0, widthM * 1000, heightM * 1000), obstacles, robots, commRangeM * 1000,
                WorldSpec.DEFAULT_MAX_MESSAGE_BYTES);
    }
}
