package robosim.protocol;

import java.nio.charset.StandardCharsets;

/**
 * A run's recording, {@code --record FILE} (version {@value #VERSION}; {@code protocol/README.md}): the
 * bytes {@code ROBOSIMREC} and a version byte, then frames, each {@code int length}, {@code length} bytes
 * ({@code byte type}, {@code long step}, then an object stream of the body) and the {@code int} CRC-32 of
 * those bytes. Types: {@link #SNAPSHOT} (a {@link WorldSnapshot}, first), {@link #STEP} (the fields
 * of the {@link PoseUpdate} the viewers got, as its {@code writeExternal} writes them, then {@code int n} and n robots' extras: {@code int robot},
 * {@code UTF contact}, {@code UTF tagged}, {@code int m} + m x ({@code UTF from}, {@code UTF to},
 * {@code UTF text}) messages delivered to it, {@code int r} + r x ({@code UTF sensor}, {@code int k} + k x
 * {@code double}) readings), {@link #END} (a {@link SimulationEnd}, last). The frame headers are the
 * index: a reader goes from frame to frame to map each step to its frame, and stops at the first frame
 * that is incomplete or fails its checksum (where a killed writer stopped).
 */
public final class RecordingFormat {
    static final byte[] MAGIC = "ROBOSIMREC".getBytes(StandardCharsets.US_ASCII);
    public static final byte VERSION = 1;
    static final byte SNAPSHOT = 1;
    static final byte STEP = 2;
    static final byte END = 3;
    /** The largest frame a reader takes, bytes (a longer length is damage, not a frame). */
    static final int MAX_FRAME_BYTES = 64 * 1024 * 1024;

    private RecordingFormat() {
    }
}
