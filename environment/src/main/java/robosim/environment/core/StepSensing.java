package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import robosim.devices.RabSensor;
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
 * Geometry's answer) and the sensors a request names (the {@link RobotSensor}s of its type and its file entry,
 * {@link Equipment}, made by {@link Sensors}; a proximity ring from Geometry's answer too), each computing its values
 * and its noise itself through one {@link SensedWorld}, whose one seeded generator they draw from in robot order, so a
 * run is reproducible bit for bit. What robots sense of each other (LEDs, range-and-bearing) is worked out once a step
 * ({@link StepMedia}).
 */
final class StepSensing {
    private static final double[] NO_RANGES = new double[0];

    private final EnvironmentMap map;
    private final WorldQueries queries;
    /** The objects where the map has them, for the queries (kept there by {@link #stepped}). */
    private final ObjectLayer things;
    private final SensedWorld world;
    private final StepMedia media;
    private SonarSensor[] sonars;
    private RobotSensor[][] sensors;
    private String[][] sensorNames;
    private double[] sensorRadius;
    private double[] height;

    StepSensing(WorldSpec spec, List<RobotProperties> properties, EnvironmentMap map, RobotActuators actuators) {
        this.map = map;
        int robots = map.robotCount();
        this.sonars = new SonarSensor[robots];
        this.sensors = new RobotSensor[robots][];
        this.sensorNames = new String[robots][];
        this.sensorRadius = new double[robots];
        this.height = new double[robots];
        this.things = new ObjectLayer(spec.scenery().objects());
        this.queries = new WorldQueries(new StaticWorld(spec.arena(), spec.obstacles()), things);
        this.media = new StepMedia(map, actuators, queries, sensorRadius, height);
        for (int i = 0; i < robots; i++) {
            equip(i, spec.robots().get(i), properties.get(i));
        }
        this.world = new SensedWorld(queries, spec, map, media, sensorRadius, height);
    }

    private void equip(int i, WorldSpec.RobotSpec robot, RobotProperties p) {
        sensorRadius[i] = p.radiusMm();
        height[i] = p.heightMm();
        sonars[i] = SonarSensor.of(p.sonars(), robot.sonarNoiseMm());
        List<robosim.devices.DeviceSpec> specs = robot.sensors();
        sensorNames[i] = new String[specs.size()];
        sensors[i] = new RobotSensor[specs.size()];
        media.receiver(i, null, 0);
        for (int k = 0; k < specs.size(); k++) {
            sensorNames[i][k] = specs.get(k).name();
            sensors[i][k] = Sensors.create(specs.get(k).kind(), specs.get(k).attributes(), p);
            if (sensors[i][k] instanceof RabSensor rab) {
                media.receiver(i, rab.model(), rab.maxMessages());
            }
        }
    }

    /** Robot {@code i}, the last, has joined (the map has it already): its sensors, and a world that sees it. */
    void add(int i, WorldSpec.RobotSpec robot, RobotProperties p) {
        sonars = java.util.Arrays.copyOf(sonars, i + 1);
        sensors = java.util.Arrays.copyOf(sensors, i + 1);
        sensorNames = java.util.Arrays.copyOf(sensorNames, i + 1);
        sensorRadius = java.util.Arrays.copyOf(sensorRadius, i + 1);
        height = java.util.Arrays.copyOf(height, i + 1);
        media.bodies(sensorRadius, height);
        equip(i, robot, p);
        world.bodies(sensorRadius, height);
    }

    /** A step's moves are done: its objects stand where the map has them now, and the media are worked out anew. */
    /** The floor and lights from now on, as the world's loop functions left them. */
    void scenery(robosim.protocol.Floor floor, List<robosim.protocol.Light> lights) {
        world.scenery(floor, lights);
    }

    void stepped() {
        for (int o = 0; o < things.count(); o++) {
            things.place(o, map.objectXMm(o), map.objectYMm(o), map.objectHeadingDeg(o));
            things.gone(o, map.objectGone(o));
        }
        media.stepped();
    }

    /** A robot that has left can no longer be sensed: its disc never meets a query. */
    void depart(int robot) {
        sensorRadius[robot] = Double.NEGATIVE_INFINITY;
    }

    /** True when robot {@code i}'s sensors named {@code names} include one the Geometry process casts rays for. */
    boolean wantsRays(int i, List<String> names) {
        for (int s = 0; s < sensorNames[i].length; s++) {
            if (sensors[i][s].info().geometry() && names.contains(sensorNames[i][s])) {
                return true;
            }
        }
        return false;
    }

    /**
     * Robot i's sonar ranges from {@code answer}, starting at range {@code first}, with its noise; the caller has
     * checked that the answer holds them.
     */
    double[] sonar(int i, GeometryStepResponse answer, int first) {
        if (map.properties(i).sonars().isEmpty()) {
            return NO_RANGES;
        }
        return sonars[i].generateSensorResponse(world.aim(i, answer, first, 0));
    }

    static double[] none() {
        return NO_RANGES;
    }

    /**
     * Robot i's sensors, in the order asked, its proximity rays in {@code answer} from ray {@code firstRay}; a name it
     * lacks or a failing sensor gets a notice.
     */
    List<SensorReading> read(int i, List<String> names, MessageRouter notices, GeometryStepResponse answer,
            int firstRay) {
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
                values = sensors[i][s].generateSensorResponse(world.aim(i, answer, 0, firstRay));
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
