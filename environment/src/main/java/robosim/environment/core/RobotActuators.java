package robosim.environment.core;

import java.util.List;
import robosim.devices.Actuators;
import robosim.devices.DeviceSpec;
import robosim.devices.LedsActuator;
import robosim.devices.RabActuator;
import robosim.devices.RobotActuator;
import robosim.protocol.Actuation;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;

/**
 * Every robot's actuators (its type's LEDs and range-and-bearing device, {@link Equipment}) and what each is set to:
 * a step's request sets them ({@link #set}) before the step's sensing reads them (the cameras the LEDs, the medium the
 * bytes sent), and viewers are shown the LEDs ({@link #leds()}). An actuator a robot lacks, or values it cannot take,
 * is a notice to the robot; nothing changes.
 */
final class RobotActuators {
    private RobotActuator[][] actuators;
    private String[][] names;
    /** Each robot's LEDs, or null; and whether any robot of the world has LEDs. */
    private LedsActuator[] leds;
    private RabActuator[] rab;
    private boolean anyLeds;

    RobotActuators(WorldSpec spec, List<RobotProperties> properties) {
        int n = properties.size();
        actuators = new RobotActuator[n][];
        names = new String[n][];
        leds = new LedsActuator[n];
        rab = new RabActuator[n];
        for (int i = 0; i < n; i++) {
            equip(i, spec.robots().get(i), properties.get(i));
        }
    }

    private void equip(int i, WorldSpec.RobotSpec robot, RobotProperties p) {
        List<DeviceSpec> specs = robot.actuators();
        actuators[i] = new RobotActuator[specs.size()];
        names[i] = new String[specs.size()];
        for (int k = 0; k < specs.size(); k++) {
            DeviceSpec d = specs.get(k);
            names[i][k] = d.name();
            actuators[i][k] = Actuators.create(d.kind(), d.attributes(), p);
            if (actuators[i][k] instanceof LedsActuator l && leds[i] == null) {
                leds[i] = l;
                anyLeds |= l.colours().length > 0;
            } else if (actuators[i][k] instanceof RabActuator r && rab[i] == null) {
                rab[i] = r;
            }
        }
    }

    /** Robot {@code i}, the last, has joined. */
    void add(int i, WorldSpec.RobotSpec robot, RobotProperties p) {
        actuators = java.util.Arrays.copyOf(actuators, i + 1);
        names = java.util.Arrays.copyOf(names, i + 1);
        leds = java.util.Arrays.copyOf(leds, i + 1);
        rab = java.util.Arrays.copyOf(rab, i + 1);
        equip(i, robot, p);
    }

    /** Robot {@code i}'s actuators set as {@code actuations} say, in order; each one it cannot do a notice. */
    void set(int i, List<Actuation> actuations, MessageRouter notices, String robotName) {
        for (Actuation a : actuations) {
            int k = 0;
            while (k < names[i].length && !names[i][k].equals(a.device())) {
                k++;
            }
            if (k == names[i].length) {
                notices.notice(i, "no actuator named " + robosim.protocol.Printable.of(a.device(), 64) + " on "
                        + robotName);
                continue;
            }
            try {
                actuators[i][k].set(a.values());
            } catch (IllegalArgumentException e) {
                notices.notice(i, e.getMessage());
            }
        }
    }

    /** Robot {@code i}'s LED colours now (none when it has no LEDs). */
    int[] leds(int i) {
        return leds[i] == null ? PoseUpdate.NO_LEDS : leds[i].colours();
    }

    /** Every robot's LED colours now, a copy; null when no robot of the world has LEDs. */
    int[][] leds() {
        if (!anyLeds) {
            return null;
        }
        int[][] out = new int[leds.length][];
        for (int i = 0; i < leds.length; i++) {
            out[i] = leds[i] == null ? PoseUpdate.NO_LEDS : leds[i].colours().clone();
        }
        return out;
    }

    /** Robot {@code i}'s LEDs' colours as it last set them (a copy; empty: it has none). */
    int[] ledsOf(int i) {
        return leds[i] == null ? PoseUpdate.NO_LEDS : leds[i].colours().clone();
    }

    /** Robot {@code i}'s range-and-bearing device, or null. */
    RabActuator rab(int i) {
        return rab[i];
    }

    int robots() {
        return actuators.length;
    }
}
