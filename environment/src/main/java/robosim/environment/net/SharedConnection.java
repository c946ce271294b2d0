package robosim.environment.net;

import robosim.environment.run.HelloCheck;
import robosim.environment.run.Hellos;
import robosim.environment.run.LoopEvent;
import robosim.environment.run.Progress;
import robosim.environment.server.ClientWorker;
import robosim.environment.server.Handshake;
import robosim.protocol.Printable;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.ObjectConnection;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SharedHello;
import robosim.protocol.SharedReplies;
import robosim.protocol.SharedRequests;

/**
 * A shared connection: several robots of one process over one socket, served by one
 * {@link RobotClientWorker} thread (the report's thread per client, a client being a connection). Each
 * robot still says hello with its own name and properties and is welcomed or refused alone; then each
 * frame the worker reads carries requests of several robots, handed to the loop as one event, and the
 * loop answers each robot into one frame per connection ({@link SharedOutput}, written after each event). A frame that names a
 * robot not on this connection, holds more requests than it has robots, or breaks off drops the
 * connection with every robot on it; the other connections go on.
 */
final class SharedConnection {
    private static final Logger LOG = LoggerFactory.getLogger(SharedConnection.class);

    private final ClientWorker worker;
    private final Handshake handshake;
    private final RobotContext context;
    /** Where this connection waits with a frame to write, once the loop has put something in it. */
    private final SharedOutput frames;
    private final ObjectConnection connection;
    /** Its robots by slot; null where one was refused. */
    private SharedRobot[] robots = new SharedRobot[0];
    private int welcomed;
    /** The next frame; the worker's until the loop has its robots' hellos, then the loop's. */
    private final SharedReplies replies = new SharedReplies();
    private boolean pending;
    private volatile boolean closed;

    SharedConnection(ClientWorker worker, RobotContext context, SharedOutput frames, ObjectConnection connection,
            Handshake handshake) {
        this.worker = worker;
        this.handshake = handshake;
        this.context = context;
        this.frames = frames;
        this.connection = connection;
    }

    /**
     * The worker's thread: the proof of the secret (when there is one: a stranger without it sends no more
     * than the header), an empty frame that asks for the robots' hellos, the hellos, the loop's verdicts, then
     * every frame of requests. A connection refused as a whole (no proof, {@code SEQUENTIAL}) gets a refusal
     * for every slot instead of the empty frame.
     */
    void serve(SharedHello header) throws IOException, InterruptedException {
        String version = handshake.version(header.protocolVersion());
        if (version != null) {
            throw new ProtocolException(version);
        }
        int n = header.robots();
        String refusal = handshake.proveSecret("robot");
        if (refusal == null) {
            refusal = context.sharedRefusal();
        }
        if (refusal != null) { // (refused as a whole, still under the handshake deadline)
            for (int slot = 0; slot < n; slot++) {
                replies.welcome(slot, RobotWelcome.refused(refusal));
            }
            handshake.refused("a shared connection of " + n + " robot(s): " + refusal);
            handshake.hold(n * refusalBytes(refusal)); // (held against the stranger budget until written)
            write();
            return;
        }
        write(); // (an empty frame: send the hellos)
        List<RobotHello> hellos = new ArrayList<>(n);
        for (int slot = 0; slot < n; slot++) {
            hellos.add(handshake.read(RobotHello.class)); // (each under the stranger's byte cap and deadline)
        }
        handshake.over();
        robots = new SharedRobot[n];
        List<Hellos.Hello> joins = new ArrayList<>();
        java.util.Set<String> names = new java.util.HashSet<>();
        List<String> refused = new ArrayList<>();
        long unwritten = 0;
        for (int slot = 0; slot < n; slot++) {
            RobotHello hello = hellos.get(slot);
            HelloCheck.Checked checked = context.check().admit(hello);
            String why = checked.refusal();
            if (why == null && !names.add(hello.name())) {
                why = "robot " + Printable.of(hello.name(), 64) + " is named twice on this connection";
            }
            if (why != null) {
                replies.welcome(slot, RobotWelcome.refused(why));
                unwritten += refusalBytes(why);
                if (refused.size() < 3) {
                    refused.add(Printable.of(hello.name(), 64) + ": " + Printable.of(why, 240));
                }
                continue;
            }
            robots[slot] = new SharedRobot(this, slot, hello.name());
            joins.add(new Hellos.Hello(robots[slot], checked.hello(), checked.index(), new CompletableFuture<>()));
        }
        hellos.clear(); // (the refused ones' names are garbage now; the accepted ones' are in their joins)
        names.clear();
        if (!refused.isEmpty()) {
            handshake.refused((n - joins.size()) + " of the " + n + " robots of a shared connection, among them "
                    + String.join("; ", refused));
        }
        if (!joins.isEmpty()) {
            List<Hellos.Hello> asked = List.copyOf(joins);
            CompletableFuture<Boolean> answered = new CompletableFuture<>();
            context.loop().post(new LoopEvent.HellosCome(new Hellos(asked, byLoop -> {
                if (byLoop && asked.stream().anyMatch(j -> j.verdict().getNow("") == null)) {
                    flush(); // (the welcomes go out before any step number)
                } // (else the connection is no robot of the world: its own thread writes the refusals, not the loop)
                answered.complete(byLoop);
            })));
            if (!handshake.verdict(answered)) { // (the loop never saw them: this thread still owns the frame)
                for (SharedRobot r : robots) {
                    if (r != null) {
                        replies.welcome(r.slot(), RobotWelcome.refused(Progress.OVER));
                    }
                }
                unwritten += asked.size() * refusalBytes(Progress.OVER);
                java.util.Arrays.fill(robots, null);
            }
            int k = 0;
            for (int slot = 0; slot < n; slot++) { // (the hellos asked are those of the robots left, in slot order)
                if (robots[slot] == null) {
                    continue;
                }
                String verdict = asked.get(k++).verdict().getNow("no answer");
                if (verdict != null) {
                    robots[slot] = null;
                    unwritten += refusalBytes(verdict);
                } else {
                    welcomed++;
                }
            }
        }
        if (welcomed == 0) {
            handshake.hold(unwritten); // (held against the stranger budget until written)
            write(); // (every robot refused: this thread writes the answers, under the connection's own clock)
            return;
        }
        handshake.accepted();
        read();
    }

    /** About what one refusal takes in a frame, bytes (its reason's characters, at most two bytes each, and a slot). */
    private static long refusalBytes(String why) {
        return 2L * why.length() + 16;
    }

    /** Every frame of requests, checked, each handed to the loop as one event. */
    private void read() throws IOException {
        long[] seenIn = new long[robots.length];
        for (long frame = 1; ; frame++) {
            SharedRequests f = connection.read(SharedRequests.class);
            if (f.count() > welcomed) {
                throw new ProtocolException("sent " + f.count() + " requests in one frame on a connection of "
                        + welcomed + " robot(s)");
            }
            List<LoopEvent> batch = new ArrayList<>(f.count());
            for (int i = 0; i < f.count(); i++) {
                int slot = f.slot(i);
                SharedRobot r = slot >= 0 && slot < robots.length ? robots[slot] : null;
                if (r == null) {
                    throw new ProtocolException("sent a request for robot slot " + slot + ", which is not a robot "
                            + "of this connection (" + welcomed + " of its " + robots.length + " were welcomed)");
                }
                if (seenIn[slot] == frame) {
                    throw new ProtocolException("sent two requests for robot " + Printable.of(r.name())
                            + " in one frame");
                }
                seenIn[slot] = frame;
                if (!r.ended()) {
                    r.check(f.request(i));
                    batch.add(new LoopEvent.Request(r, f.request(i)));
                }
            }
            if (!batch.isEmpty()) {
                context.loop().post(new LoopEvent.Batch(batch));
            }
        }
    }

    SharedReplies replies() {
        return replies;
    }

    /** Loop thread: something went into the next frame. */
    void buffered() {
        if (!pending) {
            pending = true;
            frames.add(this);
        }
    }

    /** Loop thread: writes the frame (a failure closes the connection; its reader then reports the robots gone). */
    void flush() {
        pending = false;
        if (replies.count() == 0) {
            return;
        }
        if (closed) {
            replies.clear();
            return;
        }
        try {
            write();
        } catch (IOException e) {
            closed = true; // (its reader reports the robots gone; nothing more is written meanwhile)
            String why = worker.clock().cutOffReason() != null ? worker.clock().cutOffReason() : e.getMessage();
            LOG.info("{}: could not write to its robots: {}", worker.label(), Printable.of(String.valueOf(why)));
            worker.drop();
        }
    }

    private void write() throws IOException {
        worker.clock().writing();
        try {
            connection.write(replies);
            connection.flush();
        } finally {
            worker.clock().written();
            replies.clear();
        }
    }

    boolean closed() {
        return closed;
    }

    /** The worker's thread, once the connection has closed: each of its robots in the world has left. */
    void exited(String why) {
        closed = true;
        List<LoopEvent> leaves = new ArrayList<>();
        for (SharedRobot r : robots) {
            if (r != null && r.index() >= 0) {
                leaves.add(new LoopEvent.RobotLeaves(r, why));
            }
        }
        if (!leaves.isEmpty()) {
            context.loop().post(new LoopEvent.Batch(leaves));
        }
    }
}
