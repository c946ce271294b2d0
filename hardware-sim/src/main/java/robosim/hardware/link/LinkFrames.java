package robosim.hardware.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import robosim.protocol.ProtocolException;

/**
 * The robot link's frames (and the learning link's, {@code robosim.rl.BatchLink}): a 4-byte big-endian length,
 * then that many bytes of one MessagePack value. A length of 0 or over {@link #MAX_BYTES} is refused before
 * anything of the frame is read on.
 */
public final class LinkFrames {
    /** The largest frame, bytes: a message's text (64 KiB at most) and a robot's readings fit many times over. */
    public static final int MAX_BYTES = 1 << 20;

    private LinkFrames() {
    }

    /** The next frame's bytes; null at a clean end of the stream (between frames). */
    public static byte[] read(DataInputStream in) throws IOException {
        int first = in.read();
        if (first < 0) {
            return null;
        }
        int length;
        try {
            length = (first << 24) | (in.readUnsignedByte() << 16) | (in.readUnsignedByte() << 8) | in.readUnsignedByte();
        } catch (EOFException e) {
            throw new ProtocolException("the connection ended inside a frame's length");
        }
        if (length <= 0 || length > MAX_BYTES) {
            throw new ProtocolException("a frame of " + Integer.toUnsignedString(length) + " bytes (1 to " + MAX_BYTES
                    + ")");
        }
        byte[] payload = new byte[length];
        try {
            in.readFully(payload);
        } catch (EOFException e) {
            throw new ProtocolException("the connection ended inside a frame of " + length + " bytes");
        }
        return payload;
    }

    /** Writes {@code payload} as one frame and flushes it. */
    public static void write(DataOutputStream out, byte[] payload) throws IOException {
        if (payload.length < 1 || payload.length > MAX_BYTES) {
            throw new ProtocolException("a frame of " + payload.length + " bytes to write (1 to " + MAX_BYTES + ")");
        }
        out.writeInt(payload.length);
        out.write(payload);
        out.flush();
    }
}
