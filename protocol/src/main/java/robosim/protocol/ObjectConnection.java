package robosim.protocol;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.Closeable;
import java.io.EOFException;
import java.io.Externalizable;
import java.io.IOException;
import java.io.InputStream;
import java.util.Set;
import java.io.InvalidClassException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.ObjectStreamException;
import java.io.OptionalDataException;
import java.net.Socket;

/**
 * Owns one socket and its buffered object streams (TCP_NODELAY). Messages are written unshared and
 * the output stream is reset every {@code resetEvery} messages, so neither side's handle table grows
 * without bound. Every read passes the {@link ProtocolFilter} and a per-message byte budget; anything
 * else becomes a {@link ProtocolException} naming what was wrong, after which the caller closes.
 *
 * <p>Not thread-safe: at most one thread reads and one thread writes at a time.
 */
public final class ObjectConnection implements Closeable {
    /**
     * Messages between output-stream resets. A reset costs one marker and re-sending one class
     * descriptor (about 100 bytes); the handle tables hold at most this many entries. Chosen by
     * measurement (scripts/bench-reset.sh, docs/PERFORMANCE.md): within 1% of never resetting, heap flat.
     */
    public static final int DEFAULT_RESET_EVERY = 256;
    private static final int BUFFER_BYTES = 64 * 1024;
    /** How long a client waits for the server's stream header when it sets no time (the tools' connect timeout). */
    public static final long DEFAULT_ANSWER_MS = 30_000;

    private final Socket socket;
    /** The TCP socket under {@link #socket} (the same socket without TLS). */
    private final Socket transport;
    private final ObjectOutputStream out;
    private final ObjectInputStream in;
    private final MessageBudgetInputStream budget;
    private final BufferedInputStream buffered;
    private final ProtocolFilter filter;
    private final int resetEvery;
    private int sinceReset;

    /**
     * Wraps a connected socket. Writes the stream header and then reads the peer's, so it blocks
     * until the peer does the same (bounded by the socket's SO_TIMEOUT, if set).
     *
     * @param resetEvery messages between resets; 0 never resets (for measurement only)
     */
    public ObjectConnection(Socket socket, int resetEvery) throws IOException {
        this(socket, socket, null, resetEvery, new ProtocolFilter());
    }

    /**
     * The client's end over the connected {@code raw} socket: TLS first (handshake done) when {@code keys}
     * hold the simulation's key pair, else the socket as it is. A server that answers with anything but an
     * object stream is a {@link ProtocolException} saying what it answered ({@link Greeting#describe}).
     */
    public static ObjectConnection client(Socket raw, int resetEvery, SimulationKeys keys) throws IOException {
        return client(raw, resetEvery, keys, DEFAULT_ANSWER_MS);
    }

    /**
     * As above, the server's stream header awaited at most {@code answerWithinMs} (at least
     * {@link HandshakeDeadline#MIN_MS}) from now: a port that answers nothing is then a {@link ProtocolException}
     * saying so.
     */
    public static ObjectConnection client(Socket raw, int resetEvery, SimulationKeys keys, long answerWithinMs)
            throws IOException {
        Tls tls = keys == null ? null : keys.tls();
        HandshakeDeadline deadline = HandshakeDeadline.start(raw, answerWithinMs);
        ObjectConnection c;
        try {
            c = new ObjectConnection(tls == null ? raw : tls.client(raw), raw, null, resetEvery, new ProtocolFilter());
        } catch (IOException e) {
            throw deadline.explain(e);
        }
        if (!deadline.over()) { // (the header came just as the deadline closed the socket)
            c.close();
            throw deadline.passed();
        }
        return c;
    }

    /**
     * The Environment's end over the accepted {@code raw} socket, {@code port} saying what this port is (for a
     * peer that speaks another protocol: "the Environment's robot port"). The client's first bytes are read
     * first: TLS is taken up when {@code keys} hold a key pair; a client without TLS at a port that has it is
     * answered, in its own object protocol, with a {@link SimulationEnd} saying to set ROBOSIM_KEYS; an HTTP
     * or text client gets a line saying what this port is; each of these, and a TLS client at a port without
     * keys, is then a {@link ProtocolException} saying what the client spoke.
     */
    public static ObjectConnection server(Socket raw, int resetEvery, SimulationKeys keys, String port)
            throws IOException {
        Tls tls = keys == null ? null : keys.tls();
        Greeting greeting = Greeting.read(raw.getInputStream());
        switch (greeting.kind()) {
            case OBJECT_STREAM:
                if (tls == null) {
                    return new ObjectConnection(raw, raw, greeting, resetEvery, new ProtocolFilter());
                }
                WrongClients.refuse(raw, new SimulationEnd(-1, "the Environment speaks TLS (tls=on): set ROBOSIM_KEYS "
                        + "to the simulation's keys"));
                throw new ProtocolException("it spoke without TLS; told it the Environment speaks TLS");
            case TLS:
                if (tls == null) {
                    WrongClients.turnAway(raw);
                    throw new ProtocolException("it began TLS, but this Environment has no keys (tls=off)");
                }
                javax.net.ssl.SSLSocket secured = tls.server(raw, greeting);
                Greeting inside = Greeting.read(secured.getInputStream());
                if (inside.kind() == Greeting.Kind.OBJECT_STREAM) {
                    return new ObjectConnection(secured, raw, inside, resetEvery, new ProtocolFilter());
                }
                return refuse(secured, inside, port);
            default:
                return refuse(raw, greeting, port);
        }
    }

    /**
     * Answers a client on {@code socket} (plain, or inside TLS) whose first bytes are not an object stream, in its
     * own protocol where it has one; always a {@link ProtocolException} (an EOFException when it said nothing).
     */
    private static ObjectConnection refuse(Socket socket, Greeting greeting, String port) throws IOException {
        switch (greeting.kind()) {
            case HTTP:
                WrongClients.answerHttp(socket, port);
                throw new ProtocolException("it spoke HTTP; told it this is " + port);
            case TEXT:
                WrongClients.answerLine(socket, port);
                throw new ProtocolException("it spoke a line of text; told it this is " + port);
            case NOTHING:
                socket.close();
                throw new EOFException("it closed the connection without a word");
            default:
                String what = greeting.describe(socket.getInputStream());
                WrongClients.turnAway(socket);
                throw new ProtocolException(what);
        }
    }

    ObjectConnection(Socket socket, int resetEvery, ProtocolFilter filter) throws IOException {
        this(socket, socket, null, resetEvery, filter);
    }

    /**
     * @param greeting the peer's first bytes if they have been read already (null: read here, after this end's
     *                 header has gone out)
     */
    private ObjectConnection(Socket socket, Socket transport, Greeting greeting, int resetEvery, ProtocolFilter filter)
            throws IOException {
        this.filter = filter;
        if (resetEvery < 0) {
            throw new IllegalArgumentException("resetEvery must be >= 0, got " + resetEvery);
        }
        this.socket = socket;
        this.transport = transport;
        this.resetEvery = resetEvery;
        try {
            socket.setTcpNoDelay(true);
            out = new ObjectOutputStream(new BufferedOutputStream(socket.getOutputStream(), BUFFER_BYTES));
            out.flush();
            InputStream raw = socket.getInputStream();
            Greeting first = greeting != null ? greeting : Greeting.read(raw);
            if (first.kind() != Greeting.Kind.OBJECT_STREAM) {
                throw first.kind() == Greeting.Kind.NOTHING ? new EOFException(first.describe(raw))
                        : new ProtocolException(first.describe(raw));
            }
            buffered = new BufferedInputStream(first.before(raw), BUFFER_BYTES);
            budget = new MessageBudgetInputStream(buffered, Limits.MAX_MESSAGE_BYTES);
            budget.startMessage();
            try {
                in = new ProtocolInputStream(budget, filter);
            } catch (ObjectStreamException e) {
                throw new ProtocolException("not an object stream: " + e.getMessage());
            }
        } catch (IOException | RuntimeException e) {
            closeQuietly();
            throw e;
        }
    }

    /** Writes a step number as a primitive long (never a boxed Long); not flushed. */
    public void writeStep(long step) throws IOException {
        out.writeLong(step);
    }

    /** Writes one message, unshared; not flushed. */
    public void write(Externalizable message) throws IOException {
        out.writeUnshared(message);
        if (resetEvery > 0 && ++sinceReset >= resetEvery) {
            out.reset();
            sinceReset = 0;
        }
    }

    public void flush() throws IOException {
        out.flush();
    }

    /**
     * Reads a step number written by {@link #writeStep}. The end of the stream, and (as the JDK
     * reports it) an object where a step number belongs, are an {@link EOFException}.
     */
    public long readStep() throws IOException {
        budget.startMessage();
        try {
            return in.readLong();
        } catch (OptionalDataException e) {
            throw new ProtocolException("expected a step number, got an object");
        } catch (RuntimeException e) {
            throw new ProtocolException("corrupt stream while reading a step number: " + e);
        }
    }

    /**
     * The client's side, right after it has sent its hello: reads the Environment's first answer; if it is a
     * {@link Challenge}, answers it with this process's proof (or fails, naming what to set, when {@code secret} is
     * null) and reads the answer after it. Returns that first real answer.
     */
    public Externalizable answerChallenge(SimulationKeys secret, String role) throws IOException {
        Externalizable first = read(Externalizable.class);
        if (!(first instanceof Challenge challenge)) {
            return first;
        }
        if (secret == null) {
            throw new ProtocolException("the Environment asks for the shared secret: set ROBOSIM_KEYS (the directory "
                    + "scripts/make-keys.sh made), ROBOSIM_SECRET_FILE (a file holding the secret) or ROBOSIM_SECRET");
        }
        write(new Proof(secret.prove(role, challenge.nonce())));
        flush();
        return read(Externalizable.class);
    }

    /** Reads one message of the expected type; anything else is a {@link ProtocolException}. */
    public <T extends Externalizable> T read(Class<T> type) throws IOException {
        if (type != lastType) { // (one type after another on a connection: no look-up per message)
            lastKinds = KINDS.computeIfAbsent(type, ObjectConnection::kindsOf);
            lastType = type;
        }
        return type.cast(readOneOf(type, lastKinds));
    }

    /** The reading thread's: the type last read, and the message classes it takes. */
    private Class<?> lastType;
    private Set<Class<?>> lastKinds;

    /** The protocol's message classes that are {@code type}s. */
    private static Set<Class<?>> kindsOf(Class<?> type) {
        Set<Class<?>> kinds = new java.util.HashSet<>();
        for (Class<?> c : ProtocolFilter.MESSAGE_CLASSES) {
            if (type.isAssignableFrom(c)) {
                kinds.add(c);
            }
        }
        return Set.copyOf(kinds);
    }

    private static final java.util.Map<Class<?>, Set<Class<?>>> KINDS = new java.util.concurrent.ConcurrentHashMap<>();

    /**
     * Reads the next message, which must be of one of {@code kinds} (a message of another class is refused as
     * its class is read, before anything of it is built); {@code type} names it in errors.
     */
    public Externalizable readOneOf(Class<?> type, Set<Class<?>> kinds) throws IOException {
        budget.startMessage();
        filter.beginMessage(kinds);
        Object o;
        try {
            o = in.readUnshared();
        } catch (InvalidClassException e) { // (the filter's, or the stream's own check by name)
            String why = filter.lastRejection();
            throw new ProtocolException(why.startsWith("expected ") ? why : "refused: " + (why.isEmpty() ? e.getMessage() : why));
        } catch (ClassNotFoundException e) {
            throw new ProtocolException("refused: unknown class " + e.getMessage());
        } catch (EOFException e) {
            throw budget.used() > 0 ? truncated(type) : e;
        } catch (OptionalDataException e) {
            throw new ProtocolException("expected a " + type.getSimpleName() + ", got primitive data");
        } catch (ObjectStreamException e) {
            if (budget.ended() && budget.used() > 0) {
                throw truncated(type); // (the JDK's word for it: "unexpected EOF in middle of data block")
            }
            throw new ProtocolException("corrupt stream while reading a " + type.getSimpleName() + ": " + e);
        } catch (RuntimeException e) {
            // the JDK's decoder answers some malformed streams with runtime exceptions (found by fuzzing:
            // a TC_ENUM without a class description throws NullPointerException); all are bad input
            throw new ProtocolException("corrupt stream while reading a " + type.getSimpleName() + ": " + e);
        }
        if (!type.isInstance(o)) {
            throw new ProtocolException("expected a " + type.getSimpleName() + ", got a "
                    + (o == null ? "null" : o.getClass().getSimpleName()));
        }
        return (Externalizable) o;
    }

    /** The bytes the last message read took from the stream. The reading thread only. */
    public long lastMessageBytes() {
        return budget.used();
    }

    private ProtocolException truncated(Class<?> type) {
        return new ProtocolException("the connection ended " + budget.used() + " bytes into a " + type.getSimpleName()
                + " (a truncated message)");
    }

    /**
     * True if the peer has sent something not read yet (or the stream has failed, which the next read
     * will report); never blocks. Over TLS what has arrived but is not decrypted yet counts too (TLS
     * decrypts only when read, so its own count sees nothing until then).
     */
    public boolean hasInput() {
        try {
            return in.available() > 0 || budget.available() > 0
                    || (transport != socket && transport.getInputStream().available() > 0);
        } catch (IOException e) {
            return true;
        }
    }

    /**
     * The most bytes one message may take from now on (at most {@link Limits#MAX_MESSAGE_BYTES}, the
     * default): a server lowers it to {@link Limits#MAX_HELLO_BYTES} until a client's hello is accepted.
     * Called by the reading thread, or before anything is read.
     */
    public void limitMessageBytes(long bytes) {
        if (bytes <= 0 || bytes > Limits.MAX_MESSAGE_BYTES) {
            throw new IllegalArgumentException("message byte limit must be in [1, " + Limits.MAX_MESSAGE_BYTES
                    + "], got " + bytes);
        }
        budget.budget(bytes);
    }

    /**
     * For a connection on which nothing is expected now: waits up to {@code ms} for the peer to close it
     * (end of stream or reset) and says whether it did. Reads nothing: a byte that comes instead is left
     * for the next read. The reading thread only.
     */
    public boolean closedByPeerWithin(int ms) throws IOException {
        if (hasInput()) {
            return false;
        }
        int before = socket.getSoTimeout();
        socket.setSoTimeout(Math.max(1, ms));
        try {
            buffered.mark(1);
            if (buffered.read() < 0) {
                return true;
            }
            buffered.reset();
            return false;
        } catch (java.net.SocketTimeoutException e) {
            return false;
        } catch (IOException e) {
            if (transport.isClosed()) {
                throw e; // closed on this side (dropped), not by the peer
            }
            return true;
        } finally {
            if (!transport.isClosed()) {
                socket.setSoTimeout(before);
            }
        }
    }

    /** Sets the read timeout in milliseconds (0 = none). */
    public void setReadTimeoutMs(int ms) throws IOException {
        socket.setSoTimeout(ms);
    }

    public boolean isClosed() {
        return transport.isClosed();
    }

    @Override
    public void close() {
        closeQuietly();
    }

    /**
     * Closes the TCP socket first: over TLS, closing only the TLS socket would wait for a write another
     * thread has blocked (a stuck peer), where closing the socket under it ends that write at once.
     */
    private void closeQuietly() {
        try {
            transport.close();
            socket.close();
        } catch (IOException ignored) {
            // closing: nothing left to tell the peer
        }
    }
}
