package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import robosim.environment.sensors.RobotSensor;
import robosim.environment.sensors.RobotSensors;
import robosim.environment.sensors.SensorContext;
import robosim.geometry.StaticWorld;
import robosim.geometry.WorldQueries;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.Limits;
import robosim.protocol.RobotProperties;
import robosim.protocol.SensorReading;

/**
 * The sense phase of a step, on the world after every move: sonar ranges from Geometry's answer with
 * the robot's sonar noise, and the plug-in sensors ({@link RobotSensor}s, stored with each robot) a
 * request names. All noise comes from the world's one seeded generator, in robot order, so a run is
 * reproducible bit for bit.
 */
final class StepSensing {
    private static final double[] NO_RANGES = new double[0];

    private final EnvironmentMap map;
    private final WorldQueries queries;
    private RobotSensor[][] sensors;
    private WorldSpec.SensorSpec[][] sensorSpecs;
    private double[] sensorRadius;
    private SensorContext context;
    private final Random random;

    StepSensing(WorldSpec spec, List<RobotProperties> properties, EnvironmentMap map) {
        this.map = map;
        int robots = map.robotCount();
        this.random = new Random(spec.seed());
        this.sensors = new RobotSensor[robots][];
        this.sensorSpecs = new WorldSpec.SensorSpec[robots][];
        this.sensorRadius = new double[robots];
        for (int i = 0; i < robots; i++) {
            equip(i, spec.robots().get(i), properties.get(i));
        }
        this.queries = new WorldQueries(new StaticWorld(spec.arena(), spec.obstacles()));
        this.context = new SensorContext(queries, spec.heatSources(), map.xs(), map.ys(), sensorRadius, map.headings());
    }

    private void equip(int i, WorldSpec.RobotSpec robot, RobotProperties p) {
        sensorRadius[i] = p.radiusMm();
        List<WorldSpec.SensorSpec> specs = robot.sensors();
        sensorSpecs[i] = specs.toArray(new WorldSpec.SensorSpec[0]);
        sensors[i] = new RobotSensor[specs.size()];
        for (int k = 0; k < specs.size(); k++) {
            sensors[i][k] = RobotSensors.create(specs.get(k).type(), specs.get(k).attributes());
        }
    }

    /** Robot {@code i}, the last, has joined (the map has it already): its sensors, and a context that sees it. */
    void add(int i, WorldSpec.RobotSpec robot, RobotProperties p) {
        sensors = java.util.Arrays.copyOf(sensors, i + 1);
        sensorSpecs = java.util.Arrays.copyOf(sensorSpecs, i + 1);
        sensorRadius = java.util.Arrays.copyOf(sensorRadius, i + 1);
        equip(i, robot, p);
        context = new SensorContext(queries, map.spec().heatSources(), map.xs(), map.ys(), sensorRadius,
                map.headings());
    }

    /** A robot that has left can no longer be sensed: its disc never meets a query. */
    void depart(int robot) {
        sensorRadius[robot] = Double.NEGATIVE_INFINITY;
    }

    /**
     * Robot i's sonar ranges from {@code answer}, starting at range {@code first}, with its noise; the
     * caller has checked that the answer holds them.
     */
    double[] sonar(int i, GeometryStepResponse answer, int first) {
        int n = map.properties(i).sonars().size();
        if (n == 0) {
            return NO_RANGES;
        }
        double noise = map.spec().robots().get(i).sonarNoiseMm();
        double[] sonar = new double[n];
        for (int s = 0; s < n; s++) {
            double r = answer.rangeMm(first + s);
            sonar[s] = noise > 0 ? Math.max(0, r + noise * random.nextGaussian()) : r;
        }
        return sonar;
    }

    static double[] none() {
        return NO_RANGES;
    }

    /** Robot i's plug-in sensors, in the order asked; a name it lacks or a failing sensor gets a notice. */
    List<SensorReading> read(int i, List<String> names, MessageRouter notices) {
        if (names.isEmpty()) {
            return List.of();
        }
        List<SensorReading> out = new ArrayList<>(names.size());
        for (String name : names) {
            int s = 0;
            while (s < sensorSpecs[i].length && !sensorSpecs[i][s].name().equals(name)) {
                s++;
            }
            if (s == sensorSpecs[i].length) {
                notices.notice(i, "no sensor named " + name + " on " + map.name(i));
                continue;
            }
            double[] values;
            try {
                values = sensors[i][s].generateSensorResponse(context.aim(i));
            } catch (RuntimeException e) {
                notices.notice(i, "sensor " + name + " failed: " + e);
                continue;
            }
            if (values == null || values.length > Limits.MAX_SENSOR_VALUES) {
                notices.notice(i, "sensor " + name + " gave " + (values == null ? "no values"
                        : values.length + " values, more than " + Limits.MAX_SENSOR_VALUES));
                continue;
            }
            values = values.clone();
            double noise = sensorSpecs[i][s].noise();
            if (noise > 0) {
                for (int v = 0; v < values.length; v++) {
                    values[v] += noise * random.nextGaussian();
                }
            }
            out.add(new SensorReading(name, values));
        }
        return out;
    }
}
