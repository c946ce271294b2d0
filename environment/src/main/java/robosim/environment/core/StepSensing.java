package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import robosim.devices.RobotSensor;
import robosim.devices.Sensors;
import robosim.devices.SonarSensor;
import robosim.geometry.ObjectLayer;
import robosim.geometry.StaticWorld;
import robosim.geometry.WorldQueries;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.Limits;
import robosim.protocol.RobotProperties;
import robosim.protocol.SensorReading;

/**
 * The sense phase of a step, on the world after every move: each robot's sonar (its {@link SonarSensor}, from
 * Geometry's answer) and the sensors a request names (the {@link RobotSensor}s of its file entry, made by
 * {@link Sensors}), each computing its values and its noise itself through one {@link SensedWorld}, whose one seeded
 * generator they draw from in robot order, so a run is reproducible bit for bit.
 */
final class StepSensing {
    private static final double[] NO_RANGES = new double[0];

    private final EnvironmentMap map;
    private final WorldQueries queries;
    /** The objects where the map has them, for the queries (kept there by {@link #objectsMoved}). */
    private final ObjectLayer things;
    private final SensedWorld world;
    private SonarSensor[] sonars;
    private RobotSensor[][] sensors;
    private String[][] sensorNames;
    private double[] sensorRadius;

    StepSensing(WorldSpec spec, List<RobotProperties> properties, EnvironmentMap map) {
        this.map = map;
        int robots = map.robotCount();
        this.sonars = new SonarSensor[robots];
        this.sensors = new RobotSensor[robots][];
        this.sensorNames = new String[robots][];
        this.sensorRadius = new double[robots];
        for (int i = 0; i < robots; i++) {
            equip(i, spec.robots().get(i), properties.get(i));
        }
        this.things = new ObjectLayer(spec.scenery().objects());
        this.queries = new WorldQueries(new StaticWorld(spec.arena(), spec.obstacles()), things);
        this.world = new SensedWorld(queries, spec.heatSources(), map, sensorRadius, spec.seed());
    }

    private void equip(int i, WorldSpec.RobotSpec robot, RobotProperties p) {
        sensorRadius[i] = p.radiusMm();
        sonars[i] = SonarSensor.of(p.sonars(), robot.sonarNoiseMm());
        List<WorldSpec.SensorSpec> specs = robot.sensors();
        sensorNames[i] = new String[specs.size()];
        sensors[i] = new RobotSensor[specs.size()];
        for (int k = 0; k < specs.size(); k++) {
            sensorNames[i][k] = specs.get(k).name();
            sensors[i][k] = Sensors.create(specs.get(k).type(), specs.get(k).attributes());
        }
    }

    /** Robot {@code i}, the last, has joined (the map has it already): its sensors, and a world that sees it. */
    void add(int i, WorldSpec.RobotSpec robot, RobotProperties p) {
        sonars = java.util.Arrays.copyOf(sonars, i + 1);
        sensors = java.util.Arrays.copyOf(sensors, i + 1);
        sensorNames = java.util.Arrays.copyOf(sensorNames, i + 1);
        sensorRadius = java.util.Arrays.copyOf(sensorRadius, i + 1);
        equip(i, robot, p);
        world.radii(sensorRadius);
    }

    /** The step's objects stand where the map has them now. */
    void objectsMoved() {
        for (int o = 0; o < things.count(); o++) {
            things.place(o, map.objectXMm(o), map.objectYMm(o), map.objectHeadingDeg(o));
        }
    }

    /** A robot that has left can no longer be sensed: its disc never meets a query. */
    void depart(int robot) {
        sensorRadius[robot] = Double.NEGATIVE_INFINITY;
    }

    /**
     * Robot i's sonar ranges from {@code answer}, starting at range {@code first}, with its noise; the caller has
     * checked that the answer holds them.
     */
    double[] sonar(int i, GeometryStepResponse answer, int first) {
        if (map.properties(i).sonars().isEmpty()) {
            return NO_RANGES;
        }
        return sonars[i].generateSensorResponse(world.aim(i, answer, first));
    }

    static double[] none() {
        return NO_RANGES;
    }

    /** Robot i's sensors, in the order asked; a name it lacks or a failing sensor gets a notice. */
    List<SensorReading> read(int i, List<String> names, MessageRouter notices) {
        if (names.isEmpty()) {
            return List.of();
        }
        List<SensorReading> out = new ArrayList<>(names.size());
        for (String name : names) {
            int s = 0;
            while (s < sensorNames[i].length && !sensorNames[i][s].equals(name)) {
                s++;
            }
            if (s == sensorNames[i].length) {
                notices.notice(i, "no sensor named " + name + " on " + map.name(i));
                continue;
            }
            double[] values;
            try {
                values = sensors[i][s].generateSensorResponse(world.aim(i, null, 0));
            } catch (RuntimeException e) {
                notices.notice(i, "sensor " + name + " failed: " + e);
                continue;
            }
            if (values == null || values.length > Limits.MAX_SENSOR_VALUES) {
                notices.notice(i, "sensor " + name + " gave " + (values == null ? "no values"
                        : values.length + " values, more than " + Limits.MAX_SENSOR_VALUES));
                continue;
            }
            out.add(new SensorReading(name, values.clone()));
        }
        return out;
    }
}
