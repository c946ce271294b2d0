package robosim.runner;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.List;
import java.util.Map;
import org.msgpack.core.MessagePacker;
import robosim.api.Message;
import robosim.devices.Attribute;
import robosim.devices.DeviceSpec;
import robosim.devices.SensorInfo;
import robosim.devices.Sensors;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;
import robosim.protocol.RaySpec;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;

/**
 * The ROS 2 bridge's frames (python/README.md, "From ROS 2"; Python's {@code robosim.ros2.messages} reads them): a world
 * as the bridge needs it to name, place and describe its topics, and a step's state, each one MessagePack value, from
 * a live simulation (the simulation link's {@code world} and {@code drive}) or from a recording ({@code record-tool.sh
 * export}) alike.
 * <ul>
 * <li>the world: {@code {step_ms, arena: [min_x, min_y, max_x, max_y], obstacles: [[name, [x0, y0, x1, y1, ...]],
 * ...], robots: [ROBOT, ...]}}, millimetres; ROBOT {@code {name, type, driven, radius_mm, max_speed_mm_s,
 * max_turn_deg_s, sonars: [[x, y, angle_deg, cone_deg, max_mm], ...], rays: [[x, y, angle_deg, range_mm], ...],
 * sensors: [{name, kind, attributes: {NAME: TEXT}}, ...]}}: each sensor's registered kind (or its class) and every
 * attribute of the kind, as the file gives it or by default;
 * <li>a step: {@code {step, poses: BIN, robots: {NAME: STATE}}}: {@code step} the steps completed, {@code poses} every
 * robot's x, y (mm) and heading (degrees) in the world's order as little-endian float64s, STATE {@code {sonar: BIN,
 * readings: {SENSOR: BIN}, ranges: {SENSOR: BIN}, received: [[from, text], ...]}} for each robot whose
 * senses the step holds ({@code ranges}: a proximity sensor's readings as distances, m, by its model's law turned
 * round; +infinity where nothing is in range).
 * </ul>
 */
public final class BridgeFrames {
    private BridgeFrames() {
    }

    /** A robot of the world: its name, what it is, whether the bridge drives it, and its sensors (none known: empty). */
    public record Robot(String name, RobotProperties properties, boolean driven, List<DeviceSpec> sensors) {
    }

    /** Packs the world's frame. */
    public static void world(MessagePacker p, long stepMs, Arena arena, List<ObstacleShape> obstacles,
            List<Robot> robots) throws IOException {
        p.packMapHeader(4);
        p.packString("step_ms").packLong(stepMs);
        p.packString("arena").packArrayHeader(4).packDouble(arena.minXMm()).packDouble(arena.minYMm())
                .packDouble(arena.maxXMm()).packDouble(arena.maxYMm());
        p.packString("obstacles").packArrayHeader(obstacles.size());
        for (ObstacleShape o : obstacles) {
            p.packArrayHeader(2).packString(o.name());
            double[] xy = o.xyMm();
            p.packArrayHeader(xy.length);
            for (double v : xy) {
                p.packDouble(v);
            }
        }
        p.packString("robots").packArrayHeader(robots.size());
        for (Robot r : robots) {
            RobotProperties t = r.properties();
            p.packMapHeader(9);
            p.packString("name").packString(r.name());
            p.packString("type").packString(t.type());
            p.packString("driven").packBoolean(r.driven());
            p.packString("radius_mm").packDouble(t.radiusMm());
            p.packString("max_speed_mm_s").packDouble(t.maxSpeedMmPerS());
            p.packString("max_turn_deg_s").packDouble(t.maxTurnDegPerS());
            p.packString("sonars").packArrayHeader(t.sonars().size());
            for (SonarSpec s : t.sonars()) {
                p.packArrayHeader(5).packDouble(s.xMm()).packDouble(s.yMm()).packDouble(s.angleDeg())
                        .packDouble(s.coneDeg()).packDouble(s.maxRangeMm());
            }
            p.packString("rays").packArrayHeader(t.rays().size());
            for (RaySpec s : t.rays()) {
                p.packArrayHeader(4).packDouble(s.xMm()).packDouble(s.yMm()).packDouble(s.angleDeg())
                        .packDouble(s.rangeMm());
            }
            p.packString("sensors").packArrayHeader(r.sensors().size());
            for (DeviceSpec s : r.sensors()) {
                p.packMapHeader(3).packString("name").packString(s.name()).packString("kind").packString(s.kind());
                SensorInfo kind = Sensors.info(s.kind());
                List<Attribute> attributes = kind == null ? List.of() : kind.attributes();
                p.packString("attributes").packMapHeader(attributes.size());
                for (Attribute a : attributes) {
                    String given = s.attributes().get(a.name());
                    p.packString(a.name()).packString(given != null ? given
                            : a.isChoice() ? a.shownDefault() : Attribute.plain(a.otherwise()));
                }
            }
        }
    }

    /**
     * Packs the head of a step's frame: the steps completed and every robot's pose; then a map header and, for each
     * robot in it, its name and {@link #state}.
     */
    public static void step(MessagePacker p, long step, double[] xMm, double[] yMm, double[] headingDeg)
            throws IOException {
        p.packMapHeader(3);
        p.packString("step").packLong(step);
        ByteBuffer poses = ByteBuffer.allocate(xMm.length * 3 * Double.BYTES).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < xMm.length; i++) {
            poses.putDouble(xMm[i]).putDouble(yMm[i]).putDouble(headingDeg[i]);
        }
        p.packString("poses").packBinaryHeader(poses.capacity()).addPayload(poses.array());
        p.packString("robots");
    }

    /** Packs one robot's state (its sensors' specs: for the proximity sensors' ranges). */
    public static void state(MessagePacker p, double[] sonarMm, Map<String, double[]> readings, List<DeviceSpec> sensors,
            List<Message> received) throws IOException {
        p.packMapHeader(4);
        p.packString("sonar");
        doubles(p, sonarMm == null ? new double[0] : sonarMm);
        p.packString("readings").packMapHeader(readings.size());
        for (Map.Entry<String, double[]> r : readings.entrySet()) {
            p.packString(r.getKey());
            doubles(p, r.getValue() == null ? new double[0] : r.getValue());
        }
        int proximity = 0;
        for (DeviceSpec s : sensors) {
            proximity += s.kind().equals("proximity") && readings.get(s.name()) != null ? 1 : 0;
        }
        p.packString("ranges").packMapHeader(proximity);
        for (DeviceSpec s : sensors) {
            double[] values = readings.get(s.name());
            if (s.kind().equals("proximity") && values != null) {
                String model = s.attributes().getOrDefault("model", "foot-bot");
                double[] m = new double[values.length];
                for (int k = 0; k < m.length; k++) {
                    m[k] = robosim.devices.ProximitySensor.distanceM(model, values[k]);
                }
                p.packString(s.name());
                doubles(p, m);
            }
        }
        p.packString("received").packArrayHeader(received.size());
        for (Message m : received) {
            p.packArrayHeader(2).packString(m.from()).packString(m.text());
        }
    }

    private static void doubles(MessagePacker p, double[] values) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(values.length * Double.BYTES).order(ByteOrder.LITTLE_ENDIAN);
        for (double v : values) {
            b.putDouble(v);
        }
        p.packBinaryHeader(b.capacity()).addPayload(b.array());
    }
}
