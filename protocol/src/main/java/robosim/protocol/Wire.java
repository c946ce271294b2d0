package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/** Inline encodings shared by the message classes: counted arrays and lists, no nested objects. */
final class Wire {
    private Wire() {
    }

    static void writeDoubles(ObjectOutput out, double[] values, int n) throws IOException {
        for (int i = 0; i < n; i++) {
            out.writeDouble(values[i]);
        }
    }

    static double[] readDoubles(ObjectInput in, int n) throws IOException {
        double[] values = new double[n];
        for (int i = 0; i < n; i++) {
            values[i] = in.readDouble();
        }
        return values;
    }

    static void writeEvents(ObjectOutput out, List<CommEvent> events) throws IOException {
        out.writeInt(events.size());
        for (CommEvent e : events) {
            e.write(out);
        }
    }

    static List<CommEvent> readEvents(ObjectInput in, String field) throws IOException {
        int n = Limits.checkCount(field, in.readInt(), Limits.MAX_MESSAGES_PER_STEP);
        if (n == 0) {
            return List.of();
        }
        List<CommEvent> events = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            events.add(CommEvent.read(in));
        }
        return events;
    }

    static void writeStrings(ObjectOutput out, List<String> values) throws IOException {
        out.writeInt(values.size());
        for (String s : values) {
            out.writeUTF(s);
        }
    }

    static List<String> readStrings(ObjectInput in, String field, int max) throws IOException {
        int n = Limits.checkCount(field, in.readInt(), max);
        if (n == 0) {
            return List.of();
        }
        List<String> values = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            values.add(in.readUTF());
        }
        return List.copyOf(values);
    }

    static void writeReadings(ObjectOutput out, List<SensorReading> readings) throws IOException {
        out.writeInt(readings.size());
        for (SensorReading r : readings) {
            r.write(out);
        }
    }

    static List<SensorReading> readReadings(ObjectInput in) throws IOException {
        int n = Limits.checkCount("sensor reading count", in.readInt(), Limits.MAX_SENSORS);
        if (n == 0) {
            return List.of();
        }
        List<SensorReading> readings = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            readings.add(SensorReading.read(in));
        }
        return readings;
    }

    static void writeObstacles(ObjectOutput out, List<ObstacleShape> obstacles) throws IOException {
        out.writeInt(obstacles.size());
        for (ObstacleShape o : obstacles) {
            o.write(out);
        }
    }

    static List<ObstacleShape> readObstacles(ObjectInput in) throws IOException {
        int n = Limits.checkCount("obstacle count", in.readInt(), Limits.MAX_OBSTACLES);
        List<ObstacleShape> obstacles = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            obstacles.add(ObstacleShape.read(in));
        }
        return List.copyOf(obstacles);
    }

    static void checkVersion(int version) throws ProtocolException {
        if (version != Protocol.VERSION) {
            throw new ProtocolException("protocol version " + version + " is not supported (this side speaks "
                    + Protocol.VERSION + ")");
        }
    }
}
