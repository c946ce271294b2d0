package robosim.environment.core;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import robosim.devices.DeviceSpec;
import robosim.devices.RobotType;
import robosim.devices.RobotTypes;

/**
 * A robot's devices: its type's ({@link RobotType#devices}: a foot-bot's proximity ring, light ring, ground sensors,
 * range-and-bearing, camera and LEDs) and the ones its environment file adds ({@code <sensor>}). A file's sensor of the
 * same name as one of the type's replaces it (the same kind, configured otherwise: a camera that sees farther); a
 * file may leave the type's devices on only in part ({@code devices="proximity light"}). Sensors first the type's, in
 * its order, then the file's; actuators the type's.
 */
public record Equipment(List<DeviceSpec> sensors, List<DeviceSpec> actuators) {
    public Equipment {
        sensors = List.copyOf(sensors);
        actuators = List.copyOf(actuators);
    }

    /**
     * The devices of a robot of {@code type} (a registered type's; none for a type class) with the file's sensors
     * {@code own}, and of the type's devices only those named in {@code on} (null: all).
     *
     * @throws IllegalArgumentException naming what is wrong: a name in {@code on} the type has no device of, a file's
     *     sensor that replaces a device of another kind
     */
    public static Equipment of(String type, List<DeviceSpec> own, Set<String> on) {
        RobotType t = RobotTypes.known(type);
        List<DeviceSpec> devices = t == null ? List.of() : t.devices();
        if (on != null) {
            List<String> names = devices.stream().map(DeviceSpec::name).distinct().toList();
            for (String n : on) {
                if (!names.contains(n)) {
                    throw new IllegalArgumentException("devices: a " + type + " has no device \""
                            + robosim.protocol.Printable.of(n, 64) + "\" (it has: "
                            + (names.isEmpty() ? "none" : String.join(", ", names)) + ")");
                }
            }
        }
        Map<String, DeviceSpec> sensors = new LinkedHashMap<>();
        List<DeviceSpec> actuators = new ArrayList<>();
        for (DeviceSpec d : devices) {
            if (on == null || on.contains(d.name())) {
                if (d.actuator()) {
                    actuators.add(d);
                } else {
                    sensors.put(d.name(), d);
                }
            }
        }
        for (DeviceSpec s : own) {
            DeviceSpec was = sensors.get(s.name());
            if (was != null && !was.kind().equals(s.kind())) {
                throw new IllegalArgumentException("<sensor name=\"" + robosim.protocol.Printable.of(s.name(), 64)
                        + "\"> would replace the " + type + "'s " + was.kind() + " with a " + s.kind()
                        + " (give it another name)");
            }
            sensors.put(s.name(), s);
        }
        return new Equipment(List.copyOf(sensors.values()), actuators);
    }
}
