package robosim.rl;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.devices.ActuatorValues;
import robosim.devices.Actuators;
import robosim.devices.RobotTypes;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Actuation;
import robosim.protocol.RobotProperties;
import robosim.protocol.StepRequest;

/**
 * Where each robot's devices lie in a batch's action row, after the velocities and the message's numbers: a block
 * per device name, in the order the world first names them, each as wide as the most values a robot's device of that
 * name takes; first {@code gripper} (one field: above 0.5 grips, below -0.5 lets go, between does nothing) when a
 * robot of the world has one, then each actuator of the robots' types ({@code leds}: a colour an LED; {@code rab}: a
 * message's bytes). A robot without one, or with fewer values, has fields there that it ignores. An action's device
 * values are held to their range and rounded where the device takes whole numbers (as the velocities are held to
 * the type's limits), so any policy's output is an action. A batch that does not act through its robots' devices has
 * none (no field).
 */
final class ActuatorColumns {
    /** The gripper's block's name. */
    static final String GRIPPER = "gripper";

    /** One robot's device: its name, where its block starts in the action row, and its values' shape. */
    record Column(String name, int offset, ActuatorValues values) {
    }

    private final List<List<Column>> byRobot = new ArrayList<>();
    /** Each robot's column of each device field (null: a field it ignores), from the first device field on. */
    private final List<Column[]> fields = new ArrayList<>();
    private final int first;
    private final int width;

    /** The blocks of {@code spec}'s robots' devices from field {@code first} on, or none ({@code act} false). */
    ActuatorColumns(WorldSpec spec, boolean act, int first) {
        Map<String, Integer> widths = new LinkedHashMap<>();
        List<List<String>> names = new ArrayList<>();
        List<List<ActuatorValues>> values = new ArrayList<>();
        for (WorldSpec.RobotSpec r : spec.robots()) {
            List<String> own = new ArrayList<>();
            List<ActuatorValues> each = new ArrayList<>();
            robosim.devices.RobotType type = RobotTypes.known(r.type());
            RobotProperties body = type == null ? null : type.properties();
            if (act && body != null && body.gripper() != null) {
                own.add(GRIPPER);
                each.add(new ActuatorValues(1, -1, 1, false));
            }
            for (robosim.devices.DeviceSpec d : act ? r.actuators() : List.<robosim.devices.DeviceSpec>of()) {
                own.add(d.name());
                each.add(Actuators.create(d.kind(), d.attributes(), body).values());
            }
            for (int k = 0; k < own.size(); k++) {
                widths.merge(own.get(k), each.get(k).count(), Math::max);
            }
            names.add(own);
            values.add(each);
        }
        Map<String, Integer> offsets = new LinkedHashMap<>();
        if (widths.containsKey(GRIPPER)) { // (the gripper's block first, whoever names it first)
            offsets.put(GRIPPER, first);
        }
        int at = first + (widths.containsKey(GRIPPER) ? 1 : 0);
        for (Map.Entry<String, Integer> e : widths.entrySet()) {
            if (!e.getKey().equals(GRIPPER)) {
                offsets.put(e.getKey(), at);
                at += e.getValue();
            }
        }
        this.first = first;
        this.width = at - first;
        for (int i = 0; i < names.size(); i++) {
            List<Column> columns = new ArrayList<>();
            Column[] field = new Column[width];
            for (int k = 0; k < names.get(i).size(); k++) {
                String name = names.get(i).get(k);
                Column c = new Column(name, offsets.get(name), values.get(i).get(k));
                columns.add(c);
                for (int v = 0; v < c.values().count(); v++) {
                    field[c.offset() - first + v] = c;
                }
            }
            byRobot.add(List.copyOf(columns));
            fields.add(field);
        }
    }

    /** Fields the devices add to a robot's action row. */
    int width() {
        return width;
    }

    /** Robot {@code robot}'s devices, the gripper first. */
    List<Column> of(int robot) {
        return byRobot.get(robot);
    }

    /**
     * Field {@code field} of robot {@code robot}'s action row (a device's: {@code field} at least the first device
     * field) held to its device's range and rounded where the device takes whole numbers; 0 where the robot has no
     * device.
     */
    float held(int robot, int field, float v) {
        Column c = fields.get(robot)[field - first];
        if (c == null) {
            return 0;
        }
        ActuatorValues a = c.values();
        double h = Math.max(a.low(), Math.min(a.high(), v));
        return (float) (a.whole() ? Math.rint(h) : h);
    }

    /** {@code request} with robot {@code robot}'s devices set as its action row from {@code at} says. */
    StepRequest apply(StepRequest request, int robot, float[] actions, int at) {
        List<Column> own = byRobot.get(robot);
        if (own.isEmpty()) {
            return request;
        }
        List<Actuation> set = new ArrayList<>(own.size());
        StepRequest.Gripper grip = StepRequest.Gripper.STAY;
        for (Column c : own) {
            int from = at + c.offset();
            if (c.name().equals(GRIPPER)) {
                float g = actions[from];
                grip = g > 0.5f ? StepRequest.Gripper.GRIP : g < -0.5f ? StepRequest.Gripper.RELEASE
                        : StepRequest.Gripper.STAY;
            } else {
                double[] v = new double[c.values().count()];
                for (int k = 0; k < v.length; k++) {
                    v[k] = actions[from + k];
                }
                set.add(new Actuation(c.name(), v));
            }
        }
        return request.with(set, grip);
    }
}
