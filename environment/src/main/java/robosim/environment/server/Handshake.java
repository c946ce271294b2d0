package robosim.environment.server;

import robosim.protocol.Printable;
import java.io.Externalizable;
import java.io.IOException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.Challenge;
import robosim.protocol.Limits;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Proof;
import robosim.protocol.ProtocolException;
import robosim.protocol.SimulationEnd;
import robosim.protocol.SimulationKeys;

/**
 * One connection's handshake, as its worker thread does it, the same for every kind of client (a robot, a
 * shared connection, a viewer, Geometry): until it is {@link #accepted} the client is a stranger, held to
 * {@link Limits#MAX_HELLO_BYTES} a message and to the handshake deadline of its {@link ConnectionClock};
 * with a shared secret it proves it ({@link #proveSecret}); what it has sent is held against the one
 * {@link StrangerBudget} of every port until it is accepted or answered; the loop's verdict on its hello is
 * awaited within a limit of the Environment's own; a refusal is logged once, its network text escaped and
 * cut. The worker's thread only.
 */
public final class Handshake {
    private static final Logger LOG = LoggerFactory.getLogger(Handshake.class);
    /** How long a worker waits for the loop's verdict on a hello (the loop never blocks that long), ms. */
    private static final long VERDICT_LIMIT_MS = 30_000;

    private final ClientWorker worker;
    private final ObjectConnection connection;
    private final SimulationKeys keys;
    private final StrangerBudget strangers;
    private final PortGuide guide;
    /** What this connection holds of the stranger budget now, bytes. */
    private long held;
    /** Messages read so far: a connection's first may use the budget's headroom, the others may not. */
    private int messages;

    Handshake(ClientWorker worker, ObjectConnection connection, ServerContext context) {
        this.worker = worker;
        this.connection = connection;
        this.keys = context.keys();
        this.strangers = context.strangers();
        this.guide = context.guide();
        connection.limitMessageBytes(Limits.MAX_HELLO_BYTES);
    }

    /**
     * Reads one message of the stranger's: the most it may take is taken from the stranger budget first (a
     * stranger the budget cannot hold is dropped), and what it did not use is given back; the rest stays held
     * until the handshake {@link #end}s.
     */
    public <T extends Externalizable> T read(Class<T> type) throws IOException {
        return type.cast(readOneOf(type, null));
    }

    /**
     * As {@link #read}, for a message that must be one of {@code kinds} (null: any of {@code type}); one of
     * another class is refused as its class is read, before any of it is built.
     */
    private Externalizable readOneOf(Class<? extends Externalizable> type, java.util.Set<Class<?>> kinds)
            throws IOException {
        take(Limits.MAX_HELLO_BYTES, messages++ == 0);
        try {
            return kinds == null ? connection.read(type) : connection.readOneOf(type, kinds);
        } finally {
            long unused = Limits.MAX_HELLO_BYTES - Math.min(Limits.MAX_HELLO_BYTES, connection.lastMessageBytes());
            held -= unused;
            strangers.give(unused);
        }
    }

    /**
     * Reads the client's hello, of any kind of client ({@link Port#HELLOS}; anything else is refused as its class
     * is read): one {@code here} does not take is answered with a {@link SimulationEnd} saying which port it
     * wants ({@link PortGuide#wrongPort}) and is a {@link ProtocolException}, the connection's end.
     */
    public Externalizable hello(Port here) throws IOException {
        Externalizable hello = readOneOf(Externalizable.class, Port.HELLOS);
        if (!here.takes(hello)) {
            String why = guide.wrongPort(here, hello);
            worker.send(new SimulationEnd(-1, why));
            throw new ProtocolException("a " + hello.getClass().getSimpleName() + " on " + guide.description(here)
                    + "; told it: " + why);
        }
        return hello;
    }

    /** The refusal of a client that speaks protocol {@code version}, or null if it is this server's. */
    public String version(int version) {
        return guide.version(version);
    }

    /** Takes {@code bytes} from the stranger budget for this connection (a refusal about to be written). */
    public void hold(long bytes) throws ProtocolException {
        take(bytes, false);
    }

    /** {@code first}: the connection's first message, which may use the headroom kept for newcomers. */
    private void take(long bytes, boolean first) throws ProtocolException {
        if (!strangers.take(bytes, first)) {
            throw new ProtocolException("the Environment already holds all it keeps for clients not yet accepted ("
                    + (strangers.total() >> 20) + " MiB); try again later");
        }
        held += bytes;
    }

    /** The handshake is over (accepted, refused and answered, or the connection closed): what it held is given back. */
    void end() {
        strangers.give(held);
        held = 0;
    }

    /**
     * Right after the client's hello: the proof of the secret ({@link #proveSecret}), then the handshake
     * deadline stops (what follows, the loop's verdict, is the Environment's own time, not the client's).
     * Null if the client proved the secret for {@code role} (or there is none), else the refusal.
     */
    public String heard(String role) throws IOException {
        String refusal = proveSecret(role);
        over();
        return refusal;
    }

    /**
     * With a shared secret, challenges the client (a fresh nonce) and reads its proof, under the handshake
     * deadline and the stranger's byte cap: null if it proved the secret for {@code role} (or there is none),
     * else the refusal.
     */
    public String proveSecret(String role) throws IOException {
        if (keys == null) {
            return null;
        }
        byte[] nonce = SimulationKeys.nonce();
        connection.write(new Challenge(nonce));
        connection.flush();
        Proof proof = read(Proof.class);
        return keys.proves(role, nonce, proof.mac()) ? null : "it did not prove the shared secret";
    }

    /** The client's hello is all in: the deadline no longer applies (or it has already cut the client off). */
    public void over() throws IOException {
        if (!worker.clock().handshakeOver()) {
            throw new IOException(worker.clock().cutOffReason()); // (the deadline closed the connection just before)
        }
    }

    /**
     * Waits for the loop's answer to the client's hello, at most {@link #VERDICT_LIMIT_MS}; a loop that does
     * not answer in that time (it never blocks that long) is taken as a refusal.
     */
    public <T> T verdict(CompletableFuture<T> verdict) throws IOException, InterruptedException {
        try {
            return verdict.get(VERDICT_LIMIT_MS, TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            throw new IOException("the Environment did not answer its hello in time");
        } catch (ExecutionException e) {
            throw new IOException("its hello was not answered: " + e.getCause());
        }
    }

    /**
     * The client is accepted: from now on its messages may take up to {@link Limits#MAX_MESSAGE_BYTES}, and
     * what it said is the world's, no longer held against the stranger budget.
     */
    public void accepted() {
        connection.limitMessageBytes(Limits.MAX_MESSAGE_BYTES);
        end();
    }

    /** Logs that the client was refused, and why (network text escaped; the line at most about 1 KB). */
    public void refused(String why) {
        LOG.warn("{} refused: {}", worker.label(), Printable.of(why, LOGGED_CHARS));
    }

    /** How much of a reason a log line about one connection quotes, at most. */
    public static final int LOGGED_CHARS = 900;
}
