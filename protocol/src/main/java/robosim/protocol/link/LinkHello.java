package robosim.protocol.link;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessagePackException;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.ValueType;
import robosim.protocol.Printable;
import robosim.protocol.ProtocolException;

/**
 * The first frame of a MessagePack link, the robot link's ({@code robosim.hardware.link.RobotLink}), the loop link's
 * ({@code robosim.environment.core.LoopScript}) and the learning link's
 * ({@code robosim.rl.BatchLink}) alike: a map of {@code link} (the link's name), {@code version} (a whole number),
 * {@code key} (the secret a peer this simulator started was given) and the link's own text fields, in within
 * {@link #DEADLINE_MS} of the connection ({@link LinkFrames#hello}). A hello that is late, not a map, of more than
 * {@link #MAX_FIELDS} fields, with a key that is not a text, a field of the wrong kind or a text longer than
 * {@link #MAX_TEXT} characters, more in its frame than its map, another link's, without its version or of another,
 * or without the key the link was started with, is refused: answered {@code {"error": WHY}} where the peer can still
 * hear it, and a {@link HelloRefused}. Fields it does not know are skipped.
 */
public final class LinkHello {
    /** How long a peer has from its connection to its whole hello, ms. */
    public static final long DEADLINE_MS = 10_000;
    /** The most fields a hello may have. */
    public static final int MAX_FIELDS = 16;
    /** The longest text a hello's key or field may have, characters. */
    public static final int MAX_TEXT = 1000;

    /**
     * What a link expects of its hello: its {@code name} (the hello's {@code link}), what it is called in a refusal
     * ({@code "robot link"}), its {@code version}, what its peer is called ({@code "controller"}), and its own
     * {@code fields}, texts beside {@code link}, {@code version} and {@code key}.
     */
    public record Link(String name, String called, int version, String peer, List<String> fields) {
        public Link {
            fields = List.copyOf(fields);
        }
    }

    private final DataOutputStream out;
    private final Map<String, String> texts;

    private LinkHello(DataOutputStream out, Map<String, String> texts) {
        this.out = out;
        this.texts = texts;
    }

    /**
     * Reads and checks the hello of {@code link} from {@code socket} ({@code key}: the secret its peer was given, or
     * null for none). An interrupt of this thread while it waits is the caller's end, not the peer's: its exception
     * goes out as it came.
     *
     * @throws HelloRefused the hello was late, missing or refused (answered why where it came)
     */
    public static LinkHello read(Link link, Socket socket, DataInputStream in, DataOutputStream out, String key)
            throws IOException {
        byte[] frame;
        try {
            frame = LinkFrames.hello(in, socket, DEADLINE_MS);
        } catch (ProtocolException e) {
            if (Thread.currentThread().isInterrupted()) {
                throw e;
            }
            // a frame that is none (a length of 0 or over the bound, an HTTP request, a connection ended inside it):
            // answered why where the connection still takes a frame; a late hello's was closed by its deadline
            throw socket.isClosed() ? new HelloRefused(e.getMessage())
                    : new LinkHello(out, new HashMap<>()).refuse("not a " + link.called() + "'s hello frame: "
                            + e.getMessage());
        } // (any other IOException: this thread was interrupted, as above)
        if (frame == null) {
            throw new HelloRefused("the " + link.peer() + " closed the link before its hello");
        }
        LinkHello hello = new LinkHello(out, new HashMap<>());
        String shape = "link, version, " + String.join(", ", link.fields().isEmpty() ? List.of("key") : link.fields());
        Long version = null;
        try (MessageUnpacker u = MessagePack.newDefaultUnpacker(frame)) {
            if (u.getNextFormat().getValueType() != ValueType.MAP) {
                throw hello.refuse("a hello is a map (" + shape + ")");
            }
            int fields = u.unpackMapHeader();
            if (fields > MAX_FIELDS) {
                throw hello.refuse("a hello of " + fields + " fields (" + shape + ": at most " + MAX_FIELDS + ")");
            }
            try {
                for (int i = 0; i < fields; i++) {
                    String name = text(u, "a hello's key");
                    if (name.equals("version")) {
                        version = whole(u, "version");
                    } else if (name.equals("link") || name.equals("key") || link.fields().contains(name)) {
                        hello.texts.put(name, text(u, name));
                    } else {
                        u.skipValue();
                    }
                }
                if (u.hasNext()) {
                    throw new ProtocolException("a hello frame holds more than its map");
                }
            } catch (ProtocolException e) {
                throw hello.refuse(e.getMessage());
            }
        } catch (MessagePackException e) {
            throw hello.refuse("a hello that is not MessagePack: " + LinkFrames.oneLine(e.getMessage()));
        }
        String name = hello.text("link");
        if (!link.name().equals(name)) {
            throw hello.refuse("not a " + link.called() + "'s hello (link \"" + Printable.of(name, 40) + "\", not \""
                    + link.name() + "\")");
        }
        if (version == null) {
            throw hello.refuse("a hello without its version (this simulator speaks " + link.version() + ")");
        }
        if (version != link.version()) {
            throw hello.refuse(link.called() + " version " + version + " is not supported (this simulator speaks "
                    + link.version() + ")");
        }
        String given = hello.text("key");
        if (key != null && (given == null || !MessageDigest.isEqual(key.getBytes(StandardCharsets.UTF_8),
                given.getBytes(StandardCharsets.UTF_8)))) {
            throw hello.refuse(given == null ? "a hello without the key this link was started with"
                    : "a hello with another key than this link was started with");
        }
        return hello;
    }

    /** The hello's text field {@code name}, or null when it has none. */
    public String text(String name) {
        return texts.get(name);
    }

    /** Answers {@code {"error": why}} (best effort) and makes the refusal. */
    public HelloRefused refuse(String why) {
        String reason = LinkFrames.oneLine(why);
        try {
            MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
            p.packMapHeader(1).packString("error").packString(reason);
            LinkFrames.write(out, p.toByteArray());
        } catch (IOException gone) {
            // (the refusal stands whether the peer hears it or not)
        }
        return new HelloRefused(reason);
    }

    private static String text(MessageUnpacker u, String what) throws IOException {
        if (u.getNextFormat().getValueType() != ValueType.STRING) {
            throw new ProtocolException(what + " is not a text");
        }
        String s = u.unpackString();
        if (s.length() > MAX_TEXT) {
            throw new ProtocolException(what + " is longer than " + MAX_TEXT + " characters");
        }
        return s;
    }

    private static long whole(MessageUnpacker u, String what) throws IOException {
        if (u.getNextFormat().getValueType() != ValueType.INTEGER) {
            throw new ProtocolException(what + " is not a whole number");
        }
        return u.unpackLong();
    }


    /** A hello refused, or none come: nothing was served (a hello that came was answered why). */
    public static final class HelloRefused extends ProtocolException {
        private static final long serialVersionUID = 1L;

        HelloRefused(String why) {
            super(why);
        }
    }
}
