package robosim.environment.config;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import robosim.devices.DeviceSpec;
import robosim.devices.RobotTypes;
import robosim.devices.Sensors;
import robosim.environment.core.Equipment;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.protocol.RobotProperties;

/**
 * What a robot is, as a {@code <robot>} or a {@code <join>} rule of an environment file says: its type
 * (a registered type, or a RobotType class with its radius), sonar count and noise, control class, its type's devices
 * it leaves on ({@code devices="proximity light"}) and its sensors ({@link Equipment}), each checked, each fault
 * recorded at the element; where it stands is the caller's to check.
 */
final class RobotReader {
    private static final double MM_PER_M = 1000.0;

    private RobotReader() {
    }

    /** The robot a {@code <robot>} describes ({@code el} in a fault), as the other {@code robot} reads it. */
    static RobotSpec robot(FileFaults faults, String el, EnvironmentFile.RobotXml robot) {
        return robot(faults, robot, el, robot.name, robot.type, robot.radius, robot.sonars, robot.sonarNoiseMm,
                robot.control, robot.devices, robot.sensors);
    }

    /**
     * The robot {@code element} ({@code el} in a fault) describes, standing at the origin heading 0 (the caller puts
     * it where it stands), with the devices that have no fault; null when its radius cannot be told (its type or
     * radius at fault). Every fault is recorded.
     */
    static RobotSpec robot(FileFaults faults, FileElement element, String el, String name, String type, Double radius,
            Integer sonars, Double noise, String control, String devices, List<EnvironmentFile.SensorXml> sensorXml) {
        Double radiusMm = radiusMm(faults, element, el, type, radius);
        if (sonars != null && (sonars < 0 || sonars > robosim.protocol.Limits.MAX_SONARS)) {
            faults.add(element.at, el + " sonars must be in 0.." + robosim.protocol.Limits.MAX_SONARS + ", got "
                    + sonars);
        }
        double sonarNoise = noise == null ? 0 : noise;
        if (!(sonarNoise >= 0) || Double.isInfinite(sonarNoise)) {
            faults.add(element.at, el + " sonarNoiseMm must be >= 0, got " + sonarNoise);
        }
        if (radiusMm == null) {
            sensors(faults, el, type, sensorXml); // (their faults too)
            return null;
        }
        Set<String> on = devices == null ? null : new java.util.LinkedHashSet<>(List.of(devices.trim().split("[\\s,]+")));
        if (on != null) {
            on.remove("");
        }
        Equipment equipment;
        try {
            equipment = Equipment.of(type, sensors(faults, el, type, sensorXml), on);
        } catch (IllegalArgumentException e) {
            faults.add(element.at, el + " " + e.getMessage());
            return null;
        }
        return new RobotSpec(name, type, control == null ? "" : control, 0, 0, 0, equipment.sensors(), sonarNoise,
                radiusMm, sonars == null ? -1 : sonars, equipment.actuators());
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

    /**
     * The sensors of {@code robot} (of {@code type}) that have no fault; each fault recorded at its {@code <sensor>}. A
     * sensor the Geometry process computes (a proximity ring) comes with the robot's type: a {@code <sensor>} of its
     * kind only configures the type's own, of its name.
     */
    private static List<DeviceSpec> sensors(FileFaults faults, String robot, String type,
            List<EnvironmentFile.SensorXml> xml) {
        List<DeviceSpec> out = new ArrayList<>();
        Set<String> names = new HashSet<>();
        robosim.devices.RobotType known = type == null ? null : RobotTypes.known(type);
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
            robosim.devices.SensorInfo info = Sensors.info(s.type);
            boolean ownDevice = known != null && known.devices().stream().anyMatch(d -> !d.actuator()
                    && d.name().equals(name) && d.kind().equals(s.type));
            if (info != null && info.geometry() && !ownDevice) {
                faults.add(s.at, el + " type \"" + s.type + "\" is computed by the Geometry process and comes with "
                        + "the robot's type, not a <sensor>");
                continue;
            }
            try {
                Sensors.create(s.type, s.attributes, known == null ? null : known.properties());
            } catch (IllegalArgumentException e) {
                faults.add(s.at, el + " " + e.getMessage());
                usable = false;
            }
            if (usable) {
                out.add(new DeviceSpec(name, s.type, s.attributes));
            }
        }
        return out;
    }
}
