package robosim.environment.core;

import java.util.List;
import java.util.Random;
import robosim.devices.HeatSource;
import robosim.devices.RabMessage;
import robosim.devices.SensorContext;
import robosim.geometry.WorldQueries;
import robosim.protocol.Arena;
import robosim.protocol.Floor;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.Light;

/**
 * The world as a robot's sensors see it, at the end of a step ({@link SensorContext}): the robots' poses (the map's
 * arrays, read where they lie), rays, lines of sight and contacts through the geometry library, the heat sources, the
 * floor and the lights, the ranges the Geometry process measured this step, what robots sense of each other
 * ({@link StepMedia}), and the world's one seeded generator. Aimed at one robot at a time.
 */
final class SensedWorld implements SensorContext {
    private final WorldQueries queries;
    private final List<HeatSource> heatSources;
    private Floor floor;
    private final Arena arena;
    private List<Light> lights;
    private final EnvironmentMap map;
    private final StepMedia media;
    private final Random random;
    private double[] radius;
    private double[] height;
    private int robot;
    private GeometryStepResponse answer;
    private int firstRange;
    private int firstRay;

    SensedWorld(WorldQueries queries, WorldSpec spec, EnvironmentMap map, StepMedia media, double[] radius,
            double[] height) {
        this.queries = queries;
        this.heatSources = List.copyOf(spec.heatSources());
        this.floor = spec.scenery().floor();
        this.arena = spec.arena();
        this.lights = spec.scenery().lights();
        this.map = map;
        this.media = media;
        this.radius = radius;
        this.height = height;
        this.random = new Random(spec.seed());
    }

    /** The floor and lights as the world's loop functions left them (the file's until they change them). */
    void scenery(Floor now, List<Light> lightsNow) {
        this.floor = now;
        this.lights = lightsNow;
    }

    /** The sensing radii and heights, after robots joined (a robot that left: radius -infinity, it meets no query). */
    void bodies(double[] radii, double[] heights) {
        this.radius = radii;
        this.height = heights;
    }

    /**
     * Aims at robot {@code i}, whose sonar ranges this step begin at range {@code firstSonar} of {@code g}, its
     * proximity rays at ray {@code firstProximity}.
     */
    SensedWorld aim(int i, GeometryStepResponse g, int firstSonar, int firstProximity) {
        robot = i;
        answer = g;
        firstRange = firstSonar;
        firstRay = firstProximity;
        return this;
    }

    @Override
    public int robot() {
        return robot;
    }

    @Override
    public double xMm() {
        return map.xs()[robot];
    }

    @Override
    public double yMm() {
        return map.ys()[robot];
    }

    @Override
    public double headingDeg() {
        return map.headings()[robot];
    }

    @Override
    public double radiusMm() {
        return radius[robot];
    }

    @Override
    public double ray(double worldAngleDeg, double maxMm) {
        return queries.ray(map.xs()[robot], map.ys()[robot], worldAngleDeg, maxMm, map.xs(), map.ys(), radius, robot);
    }

    @Override
    public boolean clearTo(double xMm, double yMm) {
        return queries.clear(map.xs()[robot], map.ys()[robot], xMm, yMm);
    }

    @Override
    public List<HeatSource> heatSources() {
        return heatSources;
    }

    @Override
    public int touching(double toleranceMm, double[] out) {
        return queries.touching(robot, map.xs(), map.ys(), radius, toleranceMm, out);
    }

    @Override
    public double sonarRange(int sonar) {
        return answer.rangeMm(firstRange + sonar);
    }

    @Override
    public double rayRange(int ray) {
        return answer.rayMm(firstRay + ray);
    }

    @Override
    public int floorColour(double xMm, double yMm) {
        return floor.colourAt(arena, xMm, yMm);
    }

    @Override
    public List<Light> lights() {
        return lights;
    }

    @Override
    public boolean sight(double fromZMm, double xMm, double yMm, double zMm, int other) {
        return queries.sight(map.xs()[robot], map.ys()[robot], fromZMm, xMm, yMm, zMm, map.xs(), map.ys(), radius,
                height, robot, other);
    }

    @Override
    public void leds(double rangeMm, LedVisitor visitor) {
        media.leds(robot, rangeMm, visitor);
    }

    @Override
    public List<RabMessage> rabReceived() {
        return media.received(robot);
    }

    @Override
    public double gaussian() {
        return random.nextGaussian();
    }
}
