package robosim.protocol;

import java.nio.charset.StandardCharsets;

/**
 * A run's recording, {@code --record FILE} (version {@value #VERSION}; {@code protocol/README.md}; version 6, whose steps
 * hold nothing loop functions drew, version 5, whose steps hold nothing of loop functions, version 4, whose
 * snapshot holds no scenery and whose steps no objects and LEDs, and version 3, whose views hold no reports either,
 * are read as such; versions 1 and 2 are refused): the
 * bytes {@code ROBOSIMREC} and a version byte, then frames, each {@code int length}, {@code length} bytes
 * ({@code byte type}, {@code long step}, then an object stream of the body) and the {@code int} CRC-32 of
 * those bytes. Types: {@link #SNAPSHOT} (a {@link WorldSnapshot}, first), {@link #STEP} (the fields
 * of the {@link PoseUpdate} the viewers got, as its {@code writeExternal} writes them, then {@code int n}
 * and the {@link RobotView} body of each of the n robots in the step, in world order: {@code int robot},
 * {@code double moveMm}, {@code double turnDeg}, {@code byte flags} (1 sonar asked, 2 tag asked, 4 more
 * follows) and, with flag 4, {@code UTF contact}, {@code UTF tagged}, readings, messages sent, messages
 * delivered, notices, reports), {@link #END} (a {@link SimulationEnd}, last). The frame headers are the
 * index: a reader goes from frame to frame to map each step to its frame, and stops at the first frame
 * that is incomplete or fails its checksum (where a killed writer stopped).
 */
public final class RecordingFormat {
    static final byte[] MAGIC = "ROBOSIMREC".getBytes(StandardCharsets.US_ASCII);
    public static final byte VERSION = 7;
    /** The version before: the same but for what loop functions drew over the world ({@link Traces}). */
    static final byte VERSION_WITHOUT_TRACES = RecordingVersion.WITHOUT_TRACES;
    /** The version before: the same but for what loop functions painted, switched and reported in each step. */
    static final byte VERSION_WITHOUT_EXPERIMENT = RecordingVersion.WITHOUT_EXPERIMENT;
    /** The version before: the same but for the scenery, the objects' poses and the LEDs; read as without them. */
    static final byte VERSION_WITHOUT_SCENE = RecordingVersion.WITHOUT_SCENE;
    /** The version before that: also without the reports in each robot's view; read as views without reports. */
    static final byte VERSION_WITHOUT_REPORTS = 3;
    static final byte SNAPSHOT = 1;
    static final byte STEP = 2;
    static final byte END = 3;
    /** The world again, when robots have joined: before the first step that holds them. */
    static final byte ROSTER = 4;
    /** The largest frame a reader takes, bytes (a longer length is damage, not a frame). */
    static final int MAX_FRAME_BYTES = 64 * 1024 * 1024;

    private RecordingFormat() {
    }
}
