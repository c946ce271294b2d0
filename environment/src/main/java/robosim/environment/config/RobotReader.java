package robosim.environment.config;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import robosim.environment.core.WorldSpec;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.devices.RobotTypes;
import robosim.devices.Sensors;
import robosim.protocol.RobotProperties;

/**
 * What a robot is, as a {@code <robot>} or a {@code <join>} rule of an environment file says: its type
 * (a registered type, or a RobotType class with its radius), sonar count and noise, control class and
 * sensors, each checked, each fault recorded at the element; where it stands is the caller's to check.
 */
final class RobotReader {
    private static final double MM_PER_M = 1000.0;

    private RobotReader() {
    }

    /** The robot a {@code <robot>} describes ({@code el} in a fault), as the other {@code robot} reads it. */
    static RobotSpec robot(FileFaults faults, String el, EnvironmentFile.RobotXml robot) {
        return robot(faults, robot, el, robot.name, robot.type, robot.radius, robot.sonars, robot.sonarNoiseMm,
                robot.control, robot.sensors);
    }

    /**
     * The robot {@code element} ({@code el} in a fault) describes, standing at the origin heading 0 (the caller puts
     * it where it stands), with the sensors that have no fault; null when its radius cannot be told (its type or
     * radius at fault). Every fault is recorded.
     */
    static RobotSpec robot(FileFaults faults, FileElement element, String el, String name, String type, Double radius,
            Integer sonars, Double noise, String control, List<EnvironmentFile.SensorXml> sensorXml) {
        Double radiusMm = radiusMm(faults, element, el, type, radius);
        if (sonars != null && (sonars < 0 || sonars > robosim.protocol.Limits.MAX_SONARS)) {
            faults.add(element.at, el + " sonars must be in 0.." + robosim.protocol.Limits.MAX_SONARS + ", got "
                    + sonars);
        }
        double sonarNoise = noise == null ? 0 : noise;
        if (!(sonarNoise >= 0) || Double.isInfinite(sonarNoise)) {
            faults.add(element.at, el + " sonarNoiseMm must be >= 0, got " + sonarNoise);
        }
        List<WorldSpec.SensorSpec> sensors = sensors(faults, el, sensorXml);
        return radiusMm == null ? null : new RobotSpec(name, type, control == null ? "" : control, 0, 0, 0, sensors,
                sonarNoise, radiusMm, sonars == null ? -1 : sonars);
    }

    /** The radius of a robot of {@code type}, mm: its model's, or the file's for a RobotType class; null at a fault. */
    private static Double radiusMm(FileFaults faults, FileElement element, String el, String type, Double radius) {
        if (type == null) {
            faults.add(element.at, el + " needs a type (known: " + RobotTypes.names() + ")");
            return null;
        }
        RobotProperties props = RobotTypes.properties(type);
        if (props == null && !type.contains(".")) {
            faults.add(element.at, el + " type \"" + type + "\" is not a known robot type (known: "
                    + RobotTypes.names() + ", or the class name of a RobotType with radius=\"...\")");
            return null;
        }
        if (radius == null) {
            if (props == null && !element.hadBadValue("radius")) {
                faults.add(element.at, el + " a robot of type class " + type + " needs radius=\"...\" (metres)");
            }
            return props == null ? null : props.radiusMm();
        }
        Double metres = ObstacleReader.required(faults, element, el, "radius", radius);
        if (metres == null) {
            return null;
        }
        if (!(metres > 0)) {
            faults.add(element.at, el + " radius must be > 0 m, got " + radius);
            return null;
        }
        if (props != null && Math.abs(metres * MM_PER_M - props.radiusMm()) > 1e-6) {
            faults.add(element.at, el + " radius " + radius + " m contradicts the " + type + "'s "
                    + props.radiusMm() / MM_PER_M + " m");
            return null;
        }
        return metres * MM_PER_M;
    }

    /** The sensors of {@code robot} that have no fault; each fault recorded at its {@code <sensor>}. */
    private static List<WorldSpec.SensorSpec> sensors(FileFaults faults, String robot,
            List<EnvironmentFile.SensorXml> xml) {
        List<WorldSpec.SensorSpec> out = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (EnvironmentFile.SensorXml s : xml) {
            if (s.type == null || s.type.isBlank()) {
                faults.add(s.at, robot + " <sensor> needs a type (" + Sensors.fileNames() + " or a RobotSensor class name)");
                continue;
            }
            String name = s.name == null || s.name.isBlank() ? s.type : s.name;
            String el = robot + " <sensor name=\"" + FileFaults.cut(name) + "\">";
            boolean usable = true;
            if (!names.add(name)) {
                faults.add(s.at, el + " the name is used twice on this robot");
                usable = false;
            }
            try {
                Sensors.create(s.type, s.attributes);
            } catch (IllegalArgumentException e) {
                faults.add(s.at, el + " " + e.getMessage());
                usable = false;
            }
            if (usable) {
                out.add(new WorldSpec.SensorSpec(name, s.type, s.attributes));
            }
        }
        return out;
    }
}
