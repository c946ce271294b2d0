package robosim.environment.config;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import robosim.environment.core.WorldSpec;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.protocol.RobotModels;
import robosim.protocol.RobotProperties;

/**
 * What a robot is, as a {@code <robot>} or a {@code <join>} rule of an environment file says: its type
 * (a known model, or a RobotType class with its radius), sonar count and noise, control class and
 * plug-in sensors, each checked; where it stands is the caller's to check.
 */
final class RobotReader {
    private static final double MM_PER_M = 1000.0;

    private RobotReader() {
    }

    /** The robot of element {@code el} ({@code robot}'s fields), at the given pose (mm, degrees). */
    static RobotSpec robot(String where, String el, EnvironmentFile.RobotXml robot, double x, double y, double heading)
            throws EnvironmentFileException {
        return robot(where, el, robot.name, robot.type, robot.radius, robot.sonars, robot.sonarNoiseMm, robot.control,
                robot.sensors, x, y, heading);
    }

    static RobotSpec robot(String where, String el, String name, String type, Double radius, Integer sonars,
            Double noise, String control, List<EnvironmentFile.SensorXml> sensorXml, double x, double y,
            double heading) throws EnvironmentFileException {
        if (type == null) {
            throw new EnvironmentFileException(where + ": " + el + " needs a type (known: " + RobotModels.names()
                    + ")");
        }
        RobotProperties props = RobotModels.byName(type);
        boolean classType = props == null && type.contains(".");
        if (props == null && !classType) {
            throw new EnvironmentFileException(where + ": " + el + " type \"" + type
                    + "\" is not a known robot type (known: " + RobotModels.names()
                    + ", or the class name of a RobotType with radius=\"...\")");
        }
        if (classType && radius == null) {
            throw new EnvironmentFileException(where + ": " + el + " a robot of type class " + type
                    + " needs radius=\"...\" (metres)");
        }
        double radiusMm = radius == null ? props.radiusMm() : ObstacleReader.required(where, el, "radius", radius) * MM_PER_M;
        if (!(radiusMm > 0)) {
            throw new EnvironmentFileException(where + ": " + el + " radius must be > 0 m, got " + radius);
        }
        if (props != null && Math.abs(radiusMm - props.radiusMm()) > 1e-6) {
            throw new EnvironmentFileException(where + ": " + el + " radius " + radius + " m contradicts the "
                    + type + "'s " + props.radiusMm() / MM_PER_M + " m");
        }
        if (sonars != null && (sonars < 0 || sonars > robosim.protocol.Limits.MAX_SONARS)) {
            throw new EnvironmentFileException(where + ": " + el + " sonars must be in 0.."
                    + robosim.protocol.Limits.MAX_SONARS + ", got " + sonars);
        }
        double sonarNoise = noise == null ? 0 : noise;
        if (!(sonarNoise >= 0) || Double.isInfinite(sonarNoise)) {
            throw new EnvironmentFileException(where + ": " + el + " sonarNoiseMm must be >= 0, got " + sonarNoise);
        }
        return new RobotSpec(name, type, control == null ? "" : control, x, y, heading, sensors(where, el, sensorXml),
                sonarNoise, radiusMm, sonars == null ? -1 : sonars);
    }

    static List<WorldSpec.SensorSpec> sensors(String where, String robot, List<EnvironmentFile.SensorXml> xml)
            throws EnvironmentFileException {
        List<WorldSpec.SensorSpec> out = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (EnvironmentFile.SensorXml s : xml) {
            if (s.type == null || s.type.isBlank()) {
                throw new EnvironmentFileException(where + ": " + robot + " <sensor> needs a type (laser, heat, bump "
                        + "or a RobotSensor class name)");
            }
            String name = s.name == null || s.name.isBlank() ? s.type : s.name;
            String el = robot + " <sensor name=\"" + name + "\">";
            if (!names.add(name)) {
                throw new EnvironmentFileException(where + ": " + el + " the name is used twice on this robot");
            }
            double noise = s.noise == null ? 0 : s.noise;
            if (!(noise >= 0) || Double.isInfinite(noise)) {
                throw new EnvironmentFileException(where + ": " + el + " noise must be >= 0, got " + noise);
            }
            try {
                robosim.environment.sensors.RobotSensors.create(s.type, s.attributes);
            } catch (IllegalArgumentException e) {
                throw new EnvironmentFileException(where + ": " + el + " " + e.getMessage());
            }
            out.add(new WorldSpec.SensorSpec(name, s.type, noise, s.attributes));
        }
        return out;
    }

}
