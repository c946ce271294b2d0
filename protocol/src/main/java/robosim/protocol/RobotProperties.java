package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * What a robot is: its type name, round body, speed limits and sonar layout. The Hardware
 * Simulator sends it in {@link RobotHello}; the Environment and Geometry use it (the report's
 * proposed protocol change: properties travel with the robot, not with the Environment).
 * Written inline, never as an object of its own.
 */
public record RobotProperties(String type, double radiusMm, double maxSpeedMmPerS, double maxTurnDegPerS,
        List<SonarSpec> sonars) {
    public RobotProperties {
        if (type == null || type.isBlank()) {
            throw new IllegalArgumentException("robot type must not be empty");
        }
        if (!(radiusMm > 0) || Double.isInfinite(radiusMm)) {
            throw new IllegalArgumentException("robot radiusMm must be > 0, got " + radiusMm);
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
    }

    void write(ObjectOutput out) throws IOException {
        out.writeUTF(type);
        out.writeDouble(radiusMm);
        out.writeDouble(maxSpeedMmPerS);
        out.writeDouble(maxTurnDegPerS);
        out.writeInt(sonars.size());
        for (SonarSpec s : sonars) {
            s.write(out);
        }
    }

    static RobotProperties read(ObjectInput in) throws IOException {
        String type = in.readUTF();
        double radius = in.readDouble();
        double speed = in.readDouble();
        double turn = in.readDouble();
        int n = Limits.checkCount("sonar count", in.readInt(), Limits.MAX_SONARS);
        List<SonarSpec> sonars = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            sonars.add(SonarSpec.read(in));
        }
        try {
            return new RobotProperties(type, radius, speed, turn, sonars);
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}
