package robosim.environment.core;

import java.util.List;
import java.util.Random;
import robosim.devices.HeatSource;
import robosim.devices.SensorContext;
import robosim.geometry.WorldQueries;
import robosim.protocol.GeometryStepResponse;

/**
 * The world as a robot's sensors see it, at the end of a step ({@link SensorContext}): the robots' poses (the map's
 * arrays, read where they lie), rays, lines of sight and contacts through the geometry library, the heat sources, the
 * ranges the Geometry process measured this step, and the world's one seeded generator. Aimed at one robot at a time.
 */
final class SensedWorld implements SensorContext {
    private final WorldQueries queries;
    private final List<HeatSource> heatSources;
    private final EnvironmentMap map;
    private final Random random;
    private double[] radius;
    private int robot;
    private GeometryStepResponse answer;
    private int firstRange;

    SensedWorld(WorldQueries queries, List<HeatSource> heatSources, EnvironmentMap map, double[] radius, long seed) {
        this.queries = queries;
        this.heatSources = List.copyOf(heatSources);
        this.map = map;
        this.radius = radius;
        this.random = new Random(seed);
    }

    /** The sensing radii, after robots joined (a robot that left: negative infinity, it meets no query). */
    void radii(double[] now) {
        this.radius = now;
    }

    /** Aims at robot {@code i}, whose sonar ranges this step begin at range {@code first} of {@code g}. */
    SensedWorld aim(int i, GeometryStepResponse g, int first) {
        robot = i;
        answer = g;
        firstRange = first;
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
    public double gaussian() {
        return random.nextGaussian();
    }
}
