package robosim.protocol;

import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.Closeable;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.zip.CRC32;

/**
 * Writes a run's recording (format: {@link RecordingFormat}): the snapshot, one frame per step (the
 * viewers' {@link PoseUpdate} as it went out, and each robot's {@link RobotView}: its command, contact,
 * tag, sensor readings, messages sent and delivered, notices), and the end. Every frame goes to the file whole, with
 * its length and checksum, before the next is begun, so a process killed at any moment leaves a file
 * readable up to its last complete frame. One thread.
 */
public final class RecordingWriter implements Closeable {
    private final OutputStream out;
    private final ByteArrayOutputStream frame = new ByteArrayOutputStream(64 * 1024);
    private final CRC32 crc = new CRC32();
    private long steps;
    private List<String> names = List.of();
    /** Whether each robot's view holds its sensor readings (a sweep's recording, which only metrics read, need not). */
    private final boolean readings;

    /** Creates {@code file} (it must not exist) and writes the file header. */
    public RecordingWriter(Path file) throws IOException {
        this(file, true);
    }

    /**
     * Creates {@code file} (it must not exist) and writes the file header; {@code readings} false: the robots' views
     * are written without their sensor readings (as of robots that read none), a tenth of the size where robots
     * sense much.
     */
    public RecordingWriter(Path file, boolean readings) throws IOException {
        this.readings = readings;
        this.out = new BufferedOutputStream(Files.newOutputStream(file, StandardOpenOption.CREATE_NEW,
                StandardOpenOption.WRITE), 256 * 1024);
        out.write(RecordingFormat.MAGIC);
        out.write(RecordingFormat.VERSION);
    }

    /** The world the run starts from (the first frame). */
    public void snapshot(WorldSnapshot snapshot) throws IOException {
        names = snapshot.robotNames();
        write(RecordingFormat.SNAPSHOT, snapshot.step(), o -> o.writeObject(snapshot));
    }

    /** The world again, robots having joined: the steps written after it are of this world. */
    public void roster(WorldSnapshot snapshot) throws IOException {
        names = snapshot.robotNames();
        write(RecordingFormat.ROSTER, snapshot.step(), o -> o.writeObject(snapshot));
    }

    /**
     * One step: what the viewers got, and each robot's view of it ({@link RobotView}: its command, and what
     * it got beyond its pose and sonar); {@code requests[i]} and {@code responses[i]} are robot i's, both
     * null for a robot not in the step.
     */
    public void step(PoseUpdate update, StepRequest[] requests, StepResponse[] responses) throws IOException {
        write(RecordingFormat.STEP, update.step(), o -> {
            update.writeExternal(o); // (its fields only: no class description in every frame)
            int n = 0;
            for (StepResponse r : responses) {
                n += r != null ? 1 : 0;
            }
            o.writeInt(n);
            for (int i = 0; i < responses.length; i++) {
                if (responses[i] != null) {
                    RobotView.writeBody(o, i, names.get(i), requests[i], responses[i], readings);
                }
            }
        });
        steps++;
    }

    /** The end of the run (the last frame). */
    public void end(SimulationEnd end) throws IOException {
        write(RecordingFormat.END, end.lastStep(), o -> o.writeObject(end));
    }

    /** Steps written so far. */
    public long steps() {
        return steps;
    }

    /** Hands what is written to the operating system (a killed process loses nothing written before). */
    public void flush() throws IOException {
        out.flush();
    }

    @Override
    public void close() throws IOException {
        out.close();
    }

    private interface Body {
        void write(ObjectOutputStream o) throws IOException;
    }

    /** One frame: length, type, step, the body as an object stream, CRC-32 of type, step and body. */
    private void write(byte type, long step, Body body) throws IOException {
        frame.reset();
        DataOutputStream head = new DataOutputStream(frame);
        head.writeByte(type);
        head.writeLong(step);
        try (ObjectOutputStream o = new ObjectOutputStream(frame)) {
            body.write(o);
        }
        byte[] bytes = frame.toByteArray();
        crc.reset();
        crc.update(bytes);
        DataOutputStream d = new DataOutputStream(out);
        d.writeInt(bytes.length);
        d.write(bytes);
        d.writeInt((int) crc.getValue());
    }
}
