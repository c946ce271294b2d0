package robosim.environment.core;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Random;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import robosim.environment.sensors.RobotSensor;
import robosim.environment.sensors.RobotSensors;
import robosim.environment.sensors.SensorContext;
import robosim.geometry.Kinematics;
import robosim.geometry.StaticWorld;
import robosim.geometry.WorldQueries;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotProperties;
import robosim.protocol.SensorReading;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * One simulated world and its step function. {@link #step} takes every robot's request for step k
 * and runs the phases in order: gather (route COMMEVENTs, bound each ACTION by the robot's speed
 * limits), act and collide (one {@link GeometryService} call for every ACTION and SONAR request),
 * apply (poses from the distances Geometry returns), sense (sonar from Geometry, other SENSOR
 * requests from the robot's {@link RobotSensor}s, all on the world after every move; noise from the
 * world's one seeded generator, in robot order), respond. Deterministic: the same
 * world and the same requests give the same responses, bit for bit. Not thread-safe; one caller.
 */
public final class SimulationCore {
    private static final double EPS = 1e-9;

    private final EnvironmentMap map;
    private GeometryService geometry;
    private GeometryLoss onGeometryLoss = (failed, cause) -> {
        throw cause;
    };
    private final boolean[] gone;
    private final double[] sensorRadius;
    private final MessageRouter router;
    private final int robots;
    private final double[] maxMoveMm;
    private final double[] maxTurnDeg;
    private final GeometryStepRequest geometryRequest;
    private final StepResponse[] responses;
    private final RobotSensor[][] sensors;
    private final WorldSpec.SensorSpec[][] sensorSpecs;
    private final SensorContext sensorContext;
    /** The world's one seeded generator: all sensor noise comes from it, in a fixed order. */
    private final Random random;
    /**
     * Every distinct "tagger>target" so far, first time first (bounded by robots x (robots +
     * obstacles)); replaced, never changed, when a new pair appears.
     */
    private List<String> tags = List.of();
    private long lastStep = -1;

    public SimulationCore(WorldSpec spec, List<RobotProperties> properties, GeometryService geometry) {
        this.map = new EnvironmentMap(spec, properties);
        this.geometry = geometry;
        this.robots = map.robotCount();
        Map<String, Integer> index = new HashMap<>();
        for (int i = 0; i < robots; i++) {
            index.put(map.name(i), i);
        }
        this.router = new MessageRouter(index, robots, spec.commRangeMm(), spec.maxMessageBytes());
        this.maxMoveMm = new double[robots];
        this.maxTurnDeg = new double[robots];
        double seconds = spec.timeStepMs() / 1000.0;
        for (int i = 0; i < robots; i++) {
            maxMoveMm[i] = properties.get(i).maxSpeedMmPerS() * seconds;
            maxTurnDeg[i] = properties.get(i).maxTurnDegPerS() * seconds;
        }
        this.geometryRequest = new GeometryStepRequest(robots);
        this.responses = new StepResponse[robots];
        this.random = new Random(spec.seed());
        this.sensors = new RobotSensor[robots][];
        this.sensorSpecs = new WorldSpec.SensorSpec[robots][];
        double[] radius = new double[robots];
        this.sensorRadius = radius;
        this.gone = new boolean[robots];
        for (int i = 0; i < robots; i++) {
            radius[i] = properties.get(i).radiusMm();
            List<WorldSpec.SensorSpec> specs = spec.robots().get(i).sensors();
            sensorSpecs[i] = specs.toArray(new WorldSpec.SensorSpec[0]);
            sensors[i] = new RobotSensor[specs.size()];
            for (int k = 0; k < specs.size(); k++) {
                sensors[i][k] = RobotSensors.create(specs.get(k).type(), specs.get(k).attributes());
            }
        }
        this.sensorContext = new SensorContext(new WorldQueries(new StaticWorld(spec.arena(), spec.obstacles())),
                spec.heatSources(), map.xs(), map.ys(), radius, map.headings());
    }

    /** A core that resolves geometry in-process ({@code --no-geometry}). */
    public static SimulationCore withInProcessGeometry(WorldSpec spec, List<RobotProperties> properties) {
        return new SimulationCore(spec, properties,
                new InProcessGeometry(new EnvironmentMap(spec, properties).geometryWorld()));
    }

    public EnvironmentMap map() {
        return map;
    }

    /** The last step completed, -1 before the first. */
    public long lastStep() {
        return lastStep;
    }

    /**
     * Removes a robot from the world: from the next step it neither moves, blocks, echoes nor can be
     * sensed or tagged, messages to it are refused (the sender gets a notice), and viewers are told.
     */
    public void depart(int robot) {
        router.depart(robot);
        gone[robot] = true;
        // sensor queries test each robot's disc against its radius; minus infinity never meets anything
        sensorRadius[robot] = Double.NEGATIVE_INFINITY;
        map.depart(robot);
    }

    /** What to do when the geometry service fails in the middle of a step. */
    public interface GeometryLoss {
        /**
         * Returns the service to retry the step with, or throws (the step then fails).
         *
         * @param failed the service that failed
         * @param cause why
         */
        GeometryService replace(GeometryService failed, IOException cause) throws IOException;
    }

    /** Sets the policy for a failing geometry service (default: the step fails). */
    public void onGeometryLoss(GeometryLoss policy) {
        this.onGeometryLoss = policy;
    }

    /** Resolves geometry from the next step on with {@code service} (e.g. a new Geometry process). */
    public void useGeometry(GeometryService service) {
        this.geometry = service;
    }

    public GeometryService geometry() {
        return geometry;
    }

    /**
     * Runs step {@code k}. {@code requests[i]} is robot i's request, or null for a robot that sends
     * none (departed): it stands still. Afterwards {@link #response(int)} holds each robot's answer.
     *
     * @throws ProtocolException if a request is not for step k or holds a non-finite number
     * @throws IOException if the geometry service fails
     */
    public void step(long k, StepRequest[] requests) throws IOException {
        // gather
        geometryRequest.setStep(k);
        for (int i = 0; i < robots; i++) {
            StepRequest q = requests[i];
            double move = 0;
            double turn = 0;
            boolean sonar = false;
            if (q != null) {
                if (q.step() != k) {
                    throw new ProtocolException(map.name(i) + " sent a request for step " + q.step() + " in step " + k);
                }
                move = bounded(i, "move", q.moveMm(), maxMoveMm[i], "mm");
                turn = bounded(i, "turn", q.turnDeg(), maxTurnDeg[i], "deg");
                sonar = q.wantsSonar();
                router.route(i, map.name(i), q.messages(), map);
            }
            geometryRequest.set(i, map.xMm(i), map.yMm(i), map.headingDeg(i), turn, move, sonar);
            if (gone[i]) {
                geometryRequest.setAbsent(i);
            }
        }
        // act, collide, sense: one round trip (the same request again if the service had to be replaced)
        GeometryStepResponse g;
        while (true) {
            GeometryService current = geometry;
            try {
                g = current.resolve(geometryRequest);
                if (g.step() != k || g.count() != robots) {
                    throw new ProtocolException("geometry answered step " + g.step() + " for " + g.count()
                            + " robots, expected step " + k + " for " + robots);
                }
                break;
            } catch (IOException e) {
                geometry = onGeometryLoss.replace(current, e);
            }
        }
        // apply
        for (int i = 0; i < robots; i++) {
            double h = Kinematics.turn(map.headingDeg(i), g.turnedDeg(i));
            double moved = g.movedMm(i);
            map.setPose(i, map.xMm(i) + Kinematics.dx(h, moved), map.yMm(i) + Kinematics.dy(h, moved), h);
        }
        // tag (an ACTION, after every move)
        String[] tagged = null;
        for (int i = 0; i < robots; i++) {
            if (requests[i] != null && requests[i].wantsTag()) {
                if (tagged == null) {
                    tagged = new String[robots];
                }
                tagged[i] = Tags.nearest(map, i, map.spec().tagRangeMm());
                String pair = map.name(i) + ">" + tagged[i];
                if (!tagged[i].isEmpty() && !tags.contains(pair)) {
                    List<String> more = new ArrayList<>(tags);
                    more.add(pair);
                    tags = List.copyOf(more);
                }
            }
        }
        // sense (the world after every move) and respond
        int range = 0;
        for (int i = 0; i < robots; i++) {
            double[] sonar = NO_RANGES;
            if (geometryRequest.wantsSonar(i)) {
                int n = map.properties(i).sonars().size();
                if (range + n > g.rangeCount()) {
                    throw new ProtocolException("geometry returned " + g.rangeCount() + " sonar ranges, too few");
                }
                double noise = map.spec().robots().get(i).sonarNoiseMm();
                sonar = new double[n];
                for (int s = 0; s < n; s++) {
                    double r = g.rangeMm(range++);
                    sonar[s] = noise > 0 ? Math.max(0, r + noise * random.nextGaussian()) : r;
                }
            }
            List<SensorReading> readings = requests[i] == null || requests[i].sensors().isEmpty() ? List.of()
                    : read(i, requests[i].sensors());
            responses[i] = new StepResponse(k, g.movedMm(i), g.turnedDeg(i), contactName(g, i), map.xMm(i),
                    map.yMm(i), map.headingDeg(i), sonar, router.takeInbox(i), router.takeNotices(i), readings,
                    tagged == null || tagged[i] == null ? "" : tagged[i]);
        }
        lastStep = k;
    }

    /** Robot i's plug-in sensors, in the order asked; an unknown name gets a notice. */
    private List<SensorReading> read(int i, List<String> names) {
        List<SensorReading> out = new ArrayList<>(names.size());
        for (String name : names) {
            int s = 0;
            while (s < sensorSpecs[i].length && !sensorSpecs[i][s].name().equals(name)) {
                s++;
            }
            if (s == sensorSpecs[i].length) {
                router.notice(i, "no sensor named " + name + " on " + map.name(i));
                continue;
            }
            double[] values;
            try {
                values = sensors[i][s].generateSensorResponse(sensorContext.aim(i));
            } catch (RuntimeException e) {
                router.notice(i, "sensor " + name + " failed: " + e);
                continue;
            }
            if (values == null || values.length > robosim.protocol.Limits.MAX_SENSOR_VALUES) {
                router.notice(i, "sensor " + name + " gave " + (values == null ? "no values"
                        : values.length + " values, more than " + robosim.protocol.Limits.MAX_SENSOR_VALUES));
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

    private static final double[] NO_RANGES = new double[0];

    private double bounded(int robot, String what, double value, double max, String unit) throws ProtocolException {
        if (!Double.isFinite(value)) {
            throw new ProtocolException(map.name(robot) + " asked to " + what + " by " + value);
        }
        if (Math.abs(value) > max + EPS) {
            router.notice(robot, what + " of " + value + " " + unit + " limited to " + max + " " + unit
                    + " per step by the robot's speed limit");
            return Math.copySign(max, value);
        }
        return value;
    }

    private String contactName(GeometryStepResponse g, int robot) {
        int index = g.contactIndex(robot);
        return switch (g.contactKind(robot)) {
            case GeometryStepResponse.CONTACT_ROBOT -> map.name(index);
            case GeometryStepResponse.CONTACT_OBSTACLE -> map.spec().obstacles().get(index).name();
            case GeometryStepResponse.CONTACT_ARENA -> "arena";
            default -> "";
        };
    }

    /**
     * The last step's poses and sonar ranges for viewers: a new immutable update (the ranges are
     * the responses' own arrays, which nobody changes).
     */
    public PoseUpdate viewerUpdate() {
        double[][] sonar = new double[robots][];
        for (int i = 0; i < robots; i++) {
            sonar[i] = responses[i].sonarMm();
        }
        return map.poses(lastStep, sonar, tags);
    }

    /** Every tag so far, "tagger>target", oldest first. */
    public List<String> tags() {
        return tags;
    }

    /** Robot i's response to the last step. */
    public StepResponse response(int robot) {
        return responses[robot];
    }

    public long messagesDelivered() {
        return router.delivered();
    }

    /** Messages not delivered: unknown or departed recipient, or larger than the limit. */
    public long messagesUndeliverable() {
        return router.undeliverable() + router.tooLarge();
    }

    /** Messages dropped because the recipient was out of communication range. */
    public long messagesOutOfRange() {
        return router.outOfRange();
    }
}
