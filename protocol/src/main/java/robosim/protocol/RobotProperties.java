package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * What a robot is: its type name, round body (radius, height, mass), speed limits, sonar layout, the rays of its
 * proximity sensors, where its LEDs sit and its gripper (null for none). The Hardware Simulator sends it in
 * {@link RobotHello}; the Environment and Geometry use it (the report's proposed protocol change: properties travel with
 * the robot, not with the Environment). Written inline, never as an object of its own.
 */
public record RobotProperties(String type, double radiusMm, double heightMm, double massKg, double maxSpeedMmPerS,
        double maxTurnDegPerS, List<SonarSpec> sonars, List<RaySpec> rays, List<LedSpec> leds, Gripper gripper) {
    /**
     * A gripper at the robot's front: it takes an object whose nearest point lies within {@code reachMm} of the rim and
     * within {@code halfAngleDeg} of the heading, seen from the centre.
     */
    public record Gripper(double reachMm, double halfAngleDeg) {
        public Gripper {
            if (!(reachMm >= 0) || Double.isInfinite(reachMm) || !(halfAngleDeg > 0 && halfAngleDeg <= 180)) {
                throw new IllegalArgumentException("a gripper reaches >= 0 mm within (0, 180] degrees, got " + reachMm
                        + " mm, " + halfAngleDeg + " degrees");
            }
        }
    }

    /** A robot of the first kind: its height its radius, 10 kg, no rays, no LEDs, no gripper. */
    public RobotProperties(String type, double radiusMm, double maxSpeedMmPerS, double maxTurnDegPerS,
            List<SonarSpec> sonars) {
        this(type, radiusMm, radiusMm, 10, maxSpeedMmPerS, maxTurnDegPerS, sonars, List.of(), List.of(), null);
    }

    public RobotProperties {
        if (type == null || type.isBlank()) {
            throw new IllegalArgumentException("robot type must not be empty");
        }
        if (!(radiusMm > 0) || Double.isInfinite(radiusMm)) {
            throw new IllegalArgumentException("robot radiusMm must be > 0, got " + radiusMm);
        }
        if (!(heightMm > 0) || Double.isInfinite(heightMm) || !(massKg > 0) || Double.isInfinite(massKg)) {
            throw new IllegalArgumentException("robot heightMm and massKg must be > 0, got " + heightMm + ", "
                    + massKg);
        }
        if (!(maxSpeedMmPerS > 0) || Double.isInfinite(maxSpeedMmPerS)) {
            throw new IllegalArgumentException("robot maxSpeedMmPerS must be > 0, got " + maxSpeedMmPerS);
        }
        if (!(maxTurnDegPerS > 0) || Double.isInfinite(maxTurnDegPerS)) {
            throw new IllegalArgumentException("robot maxTurnDegPerS must be > 0, got " + maxTurnDegPerS);
        }
        sonars = List.copyOf(sonars);
        if (sonars.size() > Limits.MAX_SONARS) {
            throw new IllegalArgumentException("a robot has at most " + Limits.MAX_SONARS + " sonars, got "
                    + sonars.size());
        }
        rays = List.copyOf(rays);
        if (rays.size() > Limits.MAX_RAYS) {
            throw new IllegalArgumentException("a robot has at most " + Limits.MAX_RAYS + " rays, got " + rays.size());
        }
        leds = List.copyOf(leds);
        if (leds.size() > Limits.MAX_LEDS) {
            throw new IllegalArgumentException("a robot has at most " + Limits.MAX_LEDS + " LEDs, got " + leds.size());
        }
    }

    void write(ObjectOutput out) throws IOException {
        out.writeUTF(type);
        out.writeDouble(radiusMm);
        out.writeDouble(heightMm);
        out.writeDouble(massKg);
        out.writeDouble(maxSpeedMmPerS);
        out.writeDouble(maxTurnDegPerS);
        out.writeInt(sonars.size());
        for (SonarSpec s : sonars) {
            s.write(out);
        }
        out.writeInt(rays.size());
        for (RaySpec r : rays) {
            r.write(out);
        }
        out.writeInt(leds.size());
        for (LedSpec l : leds) {
            l.write(out);
        }
        out.writeBoolean(gripper != null);
        if (gripper != null) {
            out.writeDouble(gripper.reachMm());
            out.writeDouble(gripper.halfAngleDeg());
        }
    }

    static RobotProperties read(ObjectInput in) throws IOException {
        String type = in.readUTF();
        double radius = in.readDouble();
        boolean scene = RecordingVersion.withScene(in);
        double height = scene ? in.readDouble() : radius;
        double mass = scene ? in.readDouble() : 10;
        double speed = in.readDouble();
        double turn = in.readDouble();
        int n = Limits.checkCount("sonar count", in.readInt(), Limits.MAX_SONARS);
        List<SonarSpec> sonars = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            sonars.add(SonarSpec.read(in));
        }
        List<RaySpec> rays = new ArrayList<>();
        List<LedSpec> leds = new ArrayList<>();
        Gripper gripper = null;
        try {
            if (scene) {
                int r = Limits.checkCount("ray count", in.readInt(), Limits.MAX_RAYS);
                for (int i = 0; i < r; i++) {
                    rays.add(RaySpec.read(in));
                }
                int l = Limits.checkCount("LED count", in.readInt(), Limits.MAX_LEDS);
                for (int i = 0; i < l; i++) {
                    leds.add(LedSpec.read(in));
                }
                if (in.readBoolean()) {
                    gripper = new Gripper(in.readDouble(), in.readDouble());
                }
            }
            return new RobotProperties(type, radius, height, mass, speed, turn, sonars, rays, leds, gripper);
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}
