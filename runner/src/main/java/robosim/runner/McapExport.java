package robosim.runner;

import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import robosim.api.Message;
import robosim.devices.DeviceSpec;
import robosim.devices.SensorInfo;
import robosim.devices.Sensors;
import robosim.protocol.CommEvent;
import robosim.protocol.ControlScripts;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.RobotView;
import robosim.protocol.SensorReading;
import robosim.protocol.WorldSnapshot;
import robosim.protocol.link.LinkFrames;

/**
 * {@code record-tool.sh export RUN --mcap OUT.mcap}: a recording as ROS 2 messages in an MCAP file. The recording's
 * world and steps go as the ROS 2 bridge's frames ({@link BridgeFrames}) to {@code $ROBOSIM_PYTHON -m robosim.ros2
 * export} on its standard input, which turns them into the bridge's topics and writes the file: one mapping of
 * RoboSim's state to ROS messages, the bridge's. Every robot's senses that the recording holds are exported (its
 * sonar when asked, its readings, the messages delivered to it); a sensor's attributes are not recorded, so a laser
 * is taken as the registry's default laser.
 */
final class McapExport {
    private McapExport() {
    }

    /** Exports {@code recording} into {@code out}; the exit code (0 done, 1 a failure, 2 bad input), said on stderr. */
    static int export(Path recording, Path out) {
        if (Files.exists(out)) {
            System.err.println("record-tool: " + out + ": exists already; give another --mcap");
            return 2;
        }
        Process python;
        try {
            python = new ProcessBuilder(ControlScripts.interpreter(), "-m", "robosim.ros2", "export", "--mcap",
                    out.toAbsolutePath().toString()).redirectOutput(ProcessBuilder.Redirect.INHERIT)
                    .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        } catch (IOException e) {
            System.err.println("record-tool: export needs Python with robosim[ros2] (" + ControlScripts.INTERPRETER_VARIABLE
                    + ", else python3): " + e.getMessage());
            return 1;
        }
        try (RecordingReader r = new RecordingReader(recording);
                DataOutputStream frames = new DataOutputStream(new BufferedOutputStream(python.getOutputStream(),
                        1 << 16))) {
            send(r, frames);
        } catch (IOException e) { // (the recording unreadable, or Python gone: its own words come first)
            python.destroy();
            try {
                python.waitFor();
            } catch (InterruptedException ignored) {
                Thread.currentThread().interrupt();
            }
            System.err.println("record-tool: " + e.getMessage());
            return e.getMessage() != null && e.getMessage().startsWith(recording.toString()) ? 2 : 1;
        }
        try {
            int code = python.waitFor();
            if (code != 0) {
                System.err.println("record-tool: the export (" + ControlScripts.interpreter() + " -m robosim.ros2 "
                        + "export) ended with exit code " + code + (code == 1 ? " (is robosim[ros2] installed there?)"
                        : ""));
                return 1;
            }
            return 0;
        } catch (InterruptedException e) {
            python.destroy();
            Thread.currentThread().interrupt();
            return 1;
        }
    }

    /** The world's frame, then a frame a step. */
    private static void send(RecordingReader r, DataOutputStream out) throws IOException {
        WorldSnapshot world = r.steps() == 0 ? r.snapshot() : r.snapshotAt(r.steps() - 1); // (every robot, joined too)
        List<String> names = world.robotNames();
        Map<String, List<DeviceSpec>> sensors = sensors(r, names);
        List<BridgeFrames.Robot> robots = new ArrayList<>();
        for (int i = 0; i < names.size(); i++) {
            robots.add(new BridgeFrames.Robot(names.get(i), world.robots().get(i), false,
                    sensors.getOrDefault(names.get(i), List.of())));
        }
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        BridgeFrames.world(p, world.timeStepMs(), world.arena(), world.obstacles(), robots);
        LinkFrames.write(out, p.toByteArray());
        for (int k = 0; k < r.steps(); k++) {
            RecordingReader.Step s = r.step(k);
            PoseUpdate u = s.update();
            int n = Math.min(u.count(), names.size());
            double[] x = new double[names.size()];
            double[] y = new double[names.size()];
            double[] h = new double[names.size()];
            for (int i = 0; i < n; i++) {
                x[i] = u.xMm(i);
                y[i] = u.yMm(i);
                h[i] = u.headingDeg(i);
            }
            p.clear();
            BridgeFrames.step(p, robosim.protocol.StepNumbers.shown(u.step()), x, y, h);
            p.packMapHeader(s.views().size());
            for (RobotView v : s.views()) {
                String name = v.robot() < names.size() ? names.get(v.robot()) : "robot" + v.robot();
                Map<String, double[]> readings = new LinkedHashMap<>();
                for (SensorReading reading : v.readings()) {
                    readings.put(reading.name(), reading.values());
                }
                List<Message> received = new ArrayList<>();
                for (CommEvent m : v.delivered()) {
                    received.add(new Message(m.from(), m.payload()));
                }
                p.packString(name);
                BridgeFrames.state(p, v.robot() < n ? u.sonarMm(v.robot()) : null, readings,
                        sensors.getOrDefault(name, List.of()), received);
            }
            LinkFrames.write(out, p.toByteArray());
        }
    }

    /** Each robot's sensors as the recording shows them: a reading's name, its kind guessed by the registry. */
    private static Map<String, List<DeviceSpec>> sensors(RecordingReader r, List<String> names) throws IOException {
        Map<String, Map<String, DeviceSpec>> seen = new LinkedHashMap<>();
        for (int k = 0; k < r.steps(); k++) {
            for (RobotView v : r.step(k).views()) {
                if (v.robot() >= names.size()) {
                    continue;
                }
                Map<String, DeviceSpec> of = seen.computeIfAbsent(names.get(v.robot()), n -> new LinkedHashMap<>());
                for (SensorReading reading : v.readings()) {
                    if (!of.containsKey(reading.name())) {
                        SensorInfo kind = Sensors.kindOf(reading.name(), reading.values().length);
                        of.put(reading.name(), new DeviceSpec(reading.name(), kind == null ? reading.name()
                                : kind.name(), Map.of()));
                    }
                }
            }
        }
        Map<String, List<DeviceSpec>> out = new LinkedHashMap<>();
        seen.forEach((robot, specs) -> out.put(robot, List.copyOf(specs.values())));
        return out;
    }
}
