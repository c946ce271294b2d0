package robosim.protocol.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import robosim.protocol.Printable;
import robosim.protocol.ProtocolException;

/**
 * The MessagePack links' frames (the robot link's, the loop link's, the learning link's, {@code robosim.rl.BatchLink}): a 4-byte big-endian length,
 * then that many bytes of one MessagePack value. A length of 0 or over {@link #MAX_BYTES} is refused before
 * anything of the frame is read on.
 */
public final class LinkFrames {
    /** The largest frame, bytes: a message's text (64 KiB at most) and a robot's readings fit many times over. */
    public static final int MAX_BYTES = 1 << 20;
    /** Closes a connection whose hello is late (thread {@code link-deadline}). */
    private static final ScheduledExecutorService DEADLINES = deadlines();

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

    /**
     * The hello: the next frame, which must be in within {@code deadlineMs} of now (a deadline, not a read timeout:
     * the thread {@code link-deadline} closes {@code socket} when it passes); null if the peer closed the link first.
     *
     * @throws ProtocolException "no hello within N ms", or what was wrong with the frame
     * @throws IOException the read's own failure when this thread was interrupted (the caller's end, not the peer's)
     */
    public static byte[] hello(DataInputStream in, Socket socket, long deadlineMs) throws IOException {
        ScheduledFuture<?> late = closeAfter(socket, deadlineMs);
        byte[] frame;
        try {
            frame = read(in);
        } catch (IOException e) {
            boolean inTime = late.cancel(false);
            if (Thread.currentThread().isInterrupted()) {
                throw e;
            }
            throw e instanceof ProtocolException p && inTime ? p
                    : new ProtocolException(inTime ? oneLine(e.getMessage()) : "no hello within " + deadlineMs + " ms");
        }
        if (!late.cancel(false)) {
            throw new ProtocolException("no hello within " + deadlineMs + " ms");
        }
        return frame;
    }

    /**
     * Closes {@code connection} {@code ms} from now (thread {@code link-deadline}) unless the returned future is
     * cancelled first: a deadline on what is read from it, not a timeout on each read. {@code cancel(false)} false
     * says the deadline passed.
     */
    public static ScheduledFuture<?> closeAfter(java.io.Closeable connection, long ms) {
        return DEADLINES.schedule(() -> {
            try {
                connection.close();
            } catch (IOException ignored) {
                // (closing is all)
            }
        }, ms, TimeUnit.MILLISECONDS);
    }

    /** A reason as a link says it: on one line, made safe for a log line, at most 1000 characters. */
    public static String oneLine(String s) {
        return s == null ? "" : Printable.of(s.replaceAll("\\s+", " "), 1000);
    }

    private static ScheduledExecutorService deadlines() {
        ScheduledThreadPoolExecutor e = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, "link-deadline");
            t.setDaemon(true);
            return t;
        });
        e.setRemoveOnCancelPolicy(true);
        // (idle for a second, the thread ends: a warm JVM's run leaves no thread behind, the next hello makes one)
        e.setKeepAliveTime(1, TimeUnit.SECONDS);
        e.allowCoreThreadTimeOut(true);
        return e;
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
