package robosim.protocol;

import java.io.ByteArrayInputStream;
import java.io.Closeable;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.RandomAccessFile;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.zip.CRC32;

/**
 * Reads a recording ({@link RecordingFormat}): on opening, reads every frame once, checking its length
 * and checksum, and notes where each step's frame is; then reads any step's frame directly. A file cut
 * short (its writer was killed) or damaged is read up to its last good frame, and says where and why it
 * stopped. One thread at a time.
 */
public final class RecordingReader implements Closeable {
    /** One recorded step: the viewers' update, and the view of each robot in it (world order). */
    public record Step(PoseUpdate update, List<RobotView> views) {
        /** Robot {@code robot}'s view of this step, or null if it was not in it. */
        public RobotView view(int robot) {
            for (RobotView v : views) {
                if (v.robot() == robot) {
                    return v;
                }
            }
            return null;
        }
    }

    private final Path file;
    private final RandomAccessFile in;
    /** The file's version: {@link RecordingFormat#VERSION} or an older one it reads ({@link RecordingFormat}). */
    private int version;
    private final WorldSnapshot snapshot;
    private long[] stepOffsets = new long[1024];
    private long[] stepNumbers = new long[1024];
    private int steps;
    private SimulationEnd end;
    private String cutShort;
    /** Where each roster frame is, and the index of the first recorded step after it. */
    private long[] rosterOffsets = new long[0];
    private int[] rosterFrom = new int[0];
    private int rosters;
    /** The roster frame last read, and its world. */
    private int cachedRoster = -1;
    private WorldSnapshot cached;

    /** Opens and indexes {@code file}; one line naming it and the fault if it is not a recording. */
    public RecordingReader(Path file) throws IOException {
        this.file = file;
        this.in = new RandomAccessFile(file.toFile(), "r");
        try {
            byte[] magic = new byte[RecordingFormat.MAGIC.length];
            in.readFully(magic);
            if (!Arrays.equals(magic, RecordingFormat.MAGIC)) {
                throw new IOException(file + ": not a RoboSim recording");
            }
            version = in.readByte();
            if (version != RecordingFormat.VERSION && version != RecordingFormat.VERSION_WITHOUT_TRACES
                    && version != RecordingFormat.VERSION_WITHOUT_EXPERIMENT
                    && version != RecordingFormat.VERSION_WITHOUT_SCENE
                    && version != RecordingFormat.VERSION_WITHOUT_REPORTS) {
                throw new IOException(file + ": recording version " + version + ", this RoboSim reads "
                        + RecordingFormat.VERSION);
            }
            byte[] first = frameAt(in.getFilePointer());
            if (first == null || first[0] != RecordingFormat.SNAPSHOT) {
                throw new IOException(file + ": no snapshot at the start" + (cutShort == null ? "" : " (" + cutShort + ")"));
            }
            snapshot = (WorldSnapshot) body(first).readObject();
            index();
        } catch (IOException | ClassNotFoundException | RuntimeException e) {
            in.close();
            throw e instanceof IOException io && io.getMessage() != null && io.getMessage().startsWith(file.toString())
                    ? io : new IOException(file + ": damaged: " + e);
        }
    }

    /** Reads every frame once, checking it, and notes where each step's is; stops at the first bad one. */
    private void index() throws IOException {
        long at = in.getFilePointer();
        long length = in.length();
        while (at < length) {
            byte[] frame = frameAt(at);
            if (frame == null) {
                return; // (cutShort says why)
            }
            byte type = frame[0];
            long step = java.nio.ByteBuffer.wrap(frame, 1, 8).getLong();
            if (type == RecordingFormat.STEP) {
                if (steps > 0 && step <= stepNumbers[steps - 1]) {
                    cutShort = "step " + step + " after step " + stepNumbers[steps - 1] + " at byte " + at;
                    return;
                }
                if (steps == stepOffsets.length) {
                    stepOffsets = Arrays.copyOf(stepOffsets, steps * 2);
                    stepNumbers = Arrays.copyOf(stepNumbers, steps * 2);
                }
                stepOffsets[steps] = at;
                stepNumbers[steps] = step;
                steps++;
            } else if (type == RecordingFormat.ROSTER) {
                if (rosters == rosterOffsets.length) {
                    rosterOffsets = Arrays.copyOf(rosterOffsets, rosters * 2 + 1);
                    rosterFrom = Arrays.copyOf(rosterFrom, rosters * 2 + 1);
                }
                rosterOffsets[rosters] = at;
                rosterFrom[rosters] = steps; // (the next step recorded is the first of this world)
                rosters++;
            } else if (type == RecordingFormat.END) {
                try {
                    end = (SimulationEnd) body(frame).readObject();
                } catch (ClassNotFoundException | ClassCastException e) {
                    throw new IOException("an end frame that is not a SimulationEnd");
                }
                return;
            } else {
                cutShort = "a frame of unknown type " + type + " at byte " + at;
                return;
            }
            at += 4 + frame.length + 4;
        }
    }

    /** The frame at {@code offset} (type, step, body), checked; null, noting why, if it is cut short or damaged. */
    private byte[] frameAt(long offset) throws IOException {
        in.seek(offset);
        if (in.length() - offset < 4) {
            cutShort = "an incomplete frame at byte " + offset;
            return null;
        }
        int length = in.readInt();
        if (length < 9 || length > RecordingFormat.MAX_FRAME_BYTES) {
            cutShort = "a damaged frame (length " + length + ") at byte " + offset;
            return null;
        }
        if (offset + 4 + length + 4 > in.length()) {
            cutShort = "an incomplete frame at byte " + offset;
            return null;
        }
        byte[] bytes = new byte[length];
        in.readFully(bytes);
        int sum = in.readInt();
        CRC32 crc = new CRC32();
        crc.update(bytes);
        if ((int) crc.getValue() != sum) {
            cutShort = "a frame failing its checksum at byte " + offset;
            return null;
        }
        return bytes;
    }

    private ObjectInputStream body(byte[] frame) throws IOException {
        return new ProtocolInputStream(new ByteArrayInputStream(frame, 9, frame.length - 9), new ProtocolFilter(),
                version);
    }

    public WorldSnapshot snapshot() {
        return snapshot;
    }

    /**
     * The world the i-th recorded step is of: the first snapshot, or the last roster frame before it (robots
     * joined).
     *
     * @throws IOException naming the file if that frame is damaged
     */
    public WorldSnapshot snapshotAt(int i) throws IOException {
        int r = rosters - 1;
        while (r >= 0 && rosterFrom[r] > i) {
            r--;
        }
        if (r < 0) {
            return snapshot;
        }
        if (r == cachedRoster) {
            return cached;
        }
        byte[] frame = frameAt(rosterOffsets[r]);
        try {
            cached = (WorldSnapshot) body(frame).readObject();
            cachedRoster = r;
            return cached;
        } catch (IOException | ClassNotFoundException | RuntimeException e) {
            throw new IOException(file + ": the world before step " + stepNumbers[Math.min(i, steps - 1)]
                    + ": damaged: " + e);
        }
    }

    /** Whole steps recorded. */
    public int steps() {
        return steps;
    }

    /** The step number of the i-th recorded step (0-based). */
    public long stepNumber(int i) {
        return stepNumbers[i];
    }

    /** The end of the run, or null if the file stops before it. */
    public SimulationEnd end() {
        return end;
    }

    /** Why the file stops before its end (null if it has its end or simply stops after a whole frame). */
    public String cutShort() {
        return cutShort;
    }

    /**
     * The i-th recorded step (0-based), read from its frame.
     *
     * @throws IOException naming the file if its frame is damaged
     */
    public Step step(int i) throws IOException {
        byte[] frame = frameAt(stepOffsets[i]);
        if (frame == null) {
            throw new IOException(file + ": step " + stepNumbers[i] + ": " + cutShort);
        }
        try (ObjectInputStream o = body(frame)) {
            PoseUpdate update = new PoseUpdate();
            update.readExternal(o);
            int robots = rosters == 0 ? snapshot.robotNames().size() : snapshotAt(i).robotNames().size();
            if (update.count() != robots) {
                throw new IOException(update.count() + " robots where the world has " + robots);
            }
            int n = count(o, update.count());
            List<RobotView> views = new ArrayList<>(n);
            for (int k = 0; k < n; k++) {
                RobotView v = RobotView.readRecorded(o, update.step(),
                        version > RecordingFormat.VERSION_WITHOUT_REPORTS);
                if (v.robot() >= update.count() || (k > 0 && v.robot() <= views.get(k - 1).robot())) {
                    throw new IOException("a view of robot " + v.robot() + " out of order");
                }
                views.add(v);
            }
            return new Step(update, List.copyOf(views));
        } catch (IOException | RuntimeException e) {
            throw new IOException(file + ": step " + stepNumbers[i] + ": damaged: " + e);
        }
    }

    /** A count from the file, at most {@code max} (which the frame's own size bounds). */
    private static int count(ObjectInputStream o, int max) throws IOException {
        int n = o.readInt();
        if (n < 0 || n > max) {
            throw new IOException("a count of " + n);
        }
        return n;
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
