package robosim.rl;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.devices.Sensors;
import robosim.devices.SensorValues;
import robosim.environment.core.WorldSpec;

/**
 * Where each robot's sensors (its file's {@code <sensor>}s) lie in a batch's {@code readings} array: a block of columns
 * per sensor name, in the order the world first names them, each as wide as the most values a robot's sensor of that
 * name gives; a robot without one, or with fewer values, has zeros there. Each robot's sensors are configured as the
 * world's core configures them, so their {@link SensorValues} (count, range, unit) are the observation spaces' boxes.
 * A batch that does not read its robots' sensors has none (no column).
 */
final class SensorColumns {
    /** One robot's sensor: its name, where its block starts, and its values' shape. */
    record Column(String name, int offset, SensorValues values) {
    }

    private final Map<String, Integer> offsets = new LinkedHashMap<>();
    private final List<List<Column>> byRobot = new ArrayList<>();
    private final int width;

    /** The columns of {@code spec}'s robots' sensors, or none if the batch does not read them ({@code read} false). */
    SensorColumns(WorldSpec spec, boolean read) {
        Map<String, Integer> widths = new LinkedHashMap<>();
        List<List<robosim.devices.DeviceSpec>> specs = new ArrayList<>();
        List<List<SensorValues>> values = new ArrayList<>();
        for (WorldSpec.RobotSpec r : spec.robots()) {
            List<SensorValues> each = new ArrayList<>();
            for (robosim.devices.DeviceSpec s : read ? r.sensors() : List.<robosim.devices.DeviceSpec>of()) {
                robosim.devices.RobotType type = robosim.devices.RobotTypes.known(r.type());
                SensorValues v = Sensors.create(s.kind(), s.attributes(), type == null ? null : type.properties())
                        .values(); // (mounted on its body: a proximity ring's count is its type's rays)
                each.add(v);
                widths.merge(s.name(), v.count(), Math::max);
            }
            specs.add(read ? r.sensors() : List.of());
            values.add(each);
        }
        int at = 0;
        for (Map.Entry<String, Integer> e : widths.entrySet()) {
            offsets.put(e.getKey(), at);
            at += e.getValue();
        }
        this.width = at;
        for (int i = 0; i < specs.size(); i++) {
            List<Column> columns = new ArrayList<>();
            for (int k = 0; k < specs.get(i).size(); k++) {
                String name = specs.get(i).get(k).name();
                columns.add(new Column(name, offsets.get(name), values.get(i).get(k)));
            }
            byRobot.add(List.copyOf(columns));
        }
    }

    /** Columns a robot's row has (every block). */
    int width() {
        return width;
    }

    /** Robot {@code robot}'s sensors, in its file's order. */
    List<Column> of(int robot) {
        return byRobot.get(robot);
    }

    /** The names of the sensors a robot of the world asks for each step. */
    List<String> names(int robot) {
        return byRobot.get(robot).stream().map(Column::name).toList();
    }
}
