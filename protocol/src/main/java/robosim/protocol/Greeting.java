package robosim.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * The first bytes a peer sends on a connection, read before anything is built on them, and what they say it
 * speaks: RoboSim's object protocol (Java's stream header), TLS (a handshake or alert record), HTTP (a
 * request or a status line), a line of text (the control port's protocol), something else, or nothing (it
 * closed). A port of one protocol answers a peer of another with a refusal that peer can show; a client
 * that gets anything but an object stream says what answered instead. Whoever reads it stops at
 * {@link #BYTES} (fewer only when the peer closes), and the bytes are {@link #before} the rest of the stream.
 */
public final class Greeting {
    /** What a peer's first bytes are. */
    public enum Kind {
        OBJECT_STREAM, TLS, HTTP, TEXT, OTHER, NOTHING
    }

    /** As many bytes as tell the kinds apart (Java's stream header is 4). */
    public static final int BYTES = 4;
    /** How much of a text answer a client quotes, at most. */
    private static final int QUOTED_BYTES = 120;

    private final byte[] bytes;
    private final int length;

    private Greeting(byte[] bytes, int length) {
        this.bytes = bytes;
        this.length = length;
    }

    /** The first bytes a peer sent, as a server that reads them itself (netty) has them: at most {@link #BYTES}. */
    public static Greeting of(byte[] first) {
        return new Greeting(java.util.Arrays.copyOf(first, BYTES), Math.min(first.length, BYTES));
    }

    /** Reads the peer's first {@link #BYTES} bytes (fewer only if it closes first); blocks until they come. */
    public static Greeting read(InputStream in) throws IOException {
        byte[] b = new byte[BYTES];
        int n = 0;
        while (n < BYTES) {
            int r = in.read(b, n, BYTES - n);
            if (r < 0) {
                break;
            }
            n += r;
        }
        return new Greeting(b, n);
    }

    public Kind kind() {
        if (length == 0) {
            return Kind.NOTHING;
        }
        int b0 = bytes[0] & 0xff;
        if (b0 == 0xAC && length >= 2 && (bytes[1] & 0xff) == 0xED) {
            return Kind.OBJECT_STREAM;
        }
        if ((b0 == 0x16 || b0 == 0x15) && length >= 2 && bytes[1] == 0x03) { // handshake or alert, TLS 1.x
            return Kind.TLS;
        }
        String start = new String(bytes, 0, length, StandardCharsets.ISO_8859_1);
        for (String http : new String[] {"GET ", "POST", "HEAD", "PUT ", "HTTP", "OPTI", "DELE", "PATC", "CONN"}) {
            if (start.startsWith(http)) {
                return Kind.HTTP;
            }
        }
        for (int i = 0; i < length; i++) {
            int c = bytes[i] & 0xff;
            if (c < 0x20 && c != '\t' && c != '\r' && c != '\n' || c == 0x7f) {
                return Kind.OTHER;
            }
        }
        return Kind.TEXT;
    }

    /** These bytes, then the rest of {@code rest}: what the peer sent, whole again. */
    public InputStream before(InputStream rest) {
        return new Prefixed(bytes, length, rest);
    }

    /** The bytes read, for a TLS engine that takes them as consumed already. */
    public InputStream replay() {
        return new java.io.ByteArrayInputStream(bytes, 0, length);
    }

    /**
     * An account of a peer that sent this instead of an object stream, for a one-line error:
     * a text or HTTP answer is quoted up to its first line's end (at most {@value #QUOTED_BYTES} bytes, read from
     * {@code rest} as far as they have come), escaped.
     */
    public String describe(InputStream rest) {
        switch (kind()) {
            case NOTHING:
                return "it closed the connection without a word";
            case TLS:
                return "it speaks TLS: set ROBOSIM_KEYS to the simulation's keys";
            case TEXT:
            case HTTP:
                return "it sent \"" + Printable.of(firstLine(rest), QUOTED_BYTES) + "\""
                        + (kind() == Kind.HTTP ? " (HTTP)" : "") + ", not RoboSim's object protocol";
            default:
                StringBuilder hex = new StringBuilder();
                for (int i = 0; i < length; i++) {
                    hex.append(String.format("%02X", bytes[i] & 0xff));
                }
                return "it sent bytes 0x" + hex + "..., not RoboSim's object protocol";
        }
    }

    /** The text answer's first line: these bytes and what has already arrived of the rest (never waits for more). */
    private String firstLine(InputStream rest) {
        byte[] line = java.util.Arrays.copyOf(bytes, QUOTED_BYTES);
        int n = length;
        try {
            while (n < QUOTED_BYTES && rest.available() > 0) {
                int c = rest.read();
                if (c < 0) {
                    break;
                }
                line[n++] = (byte) c;
            }
        } catch (IOException e) {
            // what came is all there is
        }
        String s = new String(line, 0, n, StandardCharsets.UTF_8);
        int end = s.indexOf('\n');
        return (end < 0 ? s : s.substring(0, end)).strip();
    }

    /**
     * The greeting's bytes, then the stream's: a read returns what is left of the greeting alone (never waits on
     * the stream for more), and {@link #available} counts both.
     */
    private static final class Prefixed extends InputStream {
        private final byte[] prefix;
        private final int length;
        private final InputStream rest;
        private int next;

        Prefixed(byte[] prefix, int length, InputStream rest) {
            this.prefix = prefix;
            this.length = length;
            this.rest = rest;
        }

        @Override
        public int read() throws IOException {
            return next < length ? prefix[next++] & 0xff : rest.read();
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            if (next < length) {
                int n = Math.min(len, length - next);
                System.arraycopy(prefix, next, b, off, n);
                next += n;
                return n;
            }
            return rest.read(b, off, len);
        }

        @Override
        public int available() throws IOException {
            return (length - next) + rest.available();
        }

        @Override
        public void close() throws IOException {
            rest.close();
        }
    }
}
