package robosim.hardware;

import java.io.EOFException;
import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.RobotControl;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SharedHello;
import robosim.protocol.SharedReplies;
import robosim.protocol.SharedRequests;
import robosim.protocol.SimulationKeys;

/**
 * Many robots of one process over one connection (protocol 6's shared connection), run on the calling
 * thread: each robot says hello with its own name and is welcomed or refused alone; then each step one
 * frame carries every robot's request and one frame brings every response. A robot whose control code
 * does not yield holds up only itself: the others' requests go first, and if the Environment releases
 * the step without it (its step timeout), it is ended here. A robot the Environment ends alone (removed,
 * dropped) ends alone here.
 */
final class SharedLink {
    private static final Logger LOG = LoggerFactory.getLogger(SharedLink.class);
    /** How long the send phase waits for one late control code before looking at what has arrived. */
    private static final long LOOK_NANOS = TimeUnit.MILLISECONDS.toNanos(50);

    private final ObjectConnection connection;
    /** The robots by slot; null once one has ended (or was refused). */
    private final HardwareSimulator[] sims;
    /** Every robot welcomed, ended or not: each one's control code is waited for at the end. */
    private final List<HardwareSimulator> welcomed;
    /** Each robot's next step, and whether its request for it is due. */
    private final long[] next;
    private final boolean[] due;
    private final SharedRequests requests = new SharedRequests();
    /** The send phase's robots whose control code was late. */
    private final List<Integer> late = new ArrayList<>();
    private int live;
    private int dueCount;
    /** A response arrived for a robot whose request had gone: the step went on. */
    private boolean stepReleased;

    private SharedLink(ObjectConnection connection, HardwareSimulator[] sims) {
        this.connection = connection;
        this.sims = sims;
        this.next = new long[sims.length];
        this.due = new boolean[sims.length];
        List<HardwareSimulator> all = new ArrayList<>();
        for (HardwareSimulator s : sims) {
            if (s != null) {
                all.add(s);
            }
        }
        this.welcomed = List.copyOf(all);
        this.live = welcomed.size();
    }

    /**
     * Says every robot's hello over {@code socket} and reads their welcomes; a robot refused is logged and
     * left out. Throws naming the reasons if every robot was refused. The Environment's first bytes are awaited
     * at most {@code answerWithinMs} (the connect timeout).
     */
    static SharedLink connect(List<HardwareSimulator> robots, Socket socket, int resetEvery, SimulationKeys keys,
            long answerWithinMs) throws IOException {
        ObjectConnection c = ObjectConnection.client(socket, resetEvery, keys, answerWithinMs);
        try {
            c.write(new SharedHello(robots.size()));
            c.flush();
            SharedReplies welcomes = frame(c.answerChallenge(keys, "robot"));
            if (welcomes.count() == 0) { // (go on: the hellos)
                for (HardwareSimulator sim : robots) {
                    c.write(sim.hello());
                }
                c.flush();
                welcomes = frame(c.read(Externalizable.class));
            }
            HardwareSimulator[] sims = new HardwareSimulator[robots.size()];
            boolean[] answered = new boolean[sims.length];
            List<String> refusals = new ArrayList<>();
            for (int i = 0; i < welcomes.count(); i++) {
                int slot = welcomes.slot(i);
                if (welcomes.kind(i) != SharedReplies.Kind.WELCOME) {
                    continue; // (a robot that joins a running world may get its first step in the same frame)
                }
                if (slot < 0 || slot >= sims.length || answered[slot]) {
                    throw new ProtocolException("the Environment welcomed robot slot " + slot + " of " + sims.length
                            + (slot >= 0 && slot < sims.length ? " twice" : ""));
                }
                answered[slot] = true;
                RobotWelcome w = welcomes.welcome(i);
                HardwareSimulator sim = robots.get(slot);
                if (w.isAccepted()) {
                    sim.welcomed(w);
                    sims[slot] = sim;
                } else {
                    String why = printable(w.reason());
                    LOG.error("the Environment refused robot {}: {}", sim.name(), why);
                    refusals.add(sim.name() + ": " + why);
                }
            }
            for (int slot = 0; slot < sims.length; slot++) {
                if (!answered[slot]) {
                    throw new ProtocolException("the Environment did not answer robot " + robots.get(slot).name()
                            + "'s hello");
                }
            }
            if (refusals.size() == sims.length) {
                throw new ProtocolException("the Environment refused every robot: " + String.join("; ", refusals));
            }
            SharedLink link = new SharedLink(c, sims);
            link.apply(welcomes, true);
            return link;
        } catch (IOException | RuntimeException e) {
            c.close();
            throw e;
        }
    }

    private static SharedReplies frame(Externalizable answer) throws ProtocolException {
        if (answer instanceof robosim.protocol.SimulationEnd refusal) { // (a port for another kind of client, or TLS)
            throw new ProtocolException(refusal.reason());
        }
        if (!(answer instanceof SharedReplies f)) {
            throw new ProtocolException("expected a frame of replies, got a " + answer.getClass().getSimpleName());
        }
        return f;
    }

    /** Network text for a log line: at most 500 characters, anything but printable text shown as '?'. */
    private static String printable(String s) {
        StringBuilder b = new StringBuilder();
        s.codePoints().limit(500).forEach(ch -> {
            int type = Character.getType(ch);
            boolean shown = type != Character.CONTROL && type != Character.FORMAT && type != Character.SURROGATE
                    && type != Character.PRIVATE_USE && type != Character.UNASSIGNED
                    && type != Character.LINE_SEPARATOR && type != Character.PARAGRAPH_SEPARATOR;
            b.appendCodePoint(shown ? ch : '?');
        });
        return s.codePointCount(0, s.length()) > 500 ? b + "..." : b.toString();
    }

    /** Runs every welcomed robot with its control code (by slot) until each one's simulation is over. */
    void run(List<RobotControl> controls) throws IOException, InterruptedException {
        try {
            for (int slot = 0; slot < sims.length; slot++) {
                if (sims[slot] != null) {
                    sims[slot].startControl(controls.get(slot));
                }
            }
            while (live > 0) {
                if (dueCount == 0) {
                    if (!take()) {
                        break;
                    }
                } else {
                    sendDue();
                }
            }
        } finally {
            connection.close();
            for (HardwareSimulator sim : sims) {
                if (sim != null) {
                    sim.finish();
                }
            }
            // every robot's control code, those the Environment ended too, finishes (its finally blocks, a
            // last report) before this returns and the process may exit
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(HardwareSimulator.CONTROL_GRACE_MS);
            for (HardwareSimulator sim : welcomed) {
                sim.awaitControlCode(TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime()));
            }
            HardwareSimulator.warnOfParameters(welcomed);
        }
    }

    /**
     * Sends every due robot's request in one frame, once each control code has yielded; those that have not
     * within {@link #LOOK_NANOS} go after, each in a frame of its own as soon as it has.
     */
    private void sendDue() throws IOException, InterruptedException {
        late.clear();
        requests.clear();
        long deadline = System.nanoTime() + LOOK_NANOS;
        for (int slot = 0; slot < sims.length; slot++) {
            if (due[slot]) {
                if (sims[slot].link().awaitControlFor(Math.max(0, deadline - System.nanoTime()))) {
                    add(slot);
                } else {
                    late.add(slot);
                }
            }
        }
        write();
        stepReleased = false;
        for (int l = 0; l < late.size(); l++) {
            int slot = late.get(l);
            if (slot < 0) {
                continue; // (sent already, with an earlier late one)
            }
            while (due[slot] && !sims[slot].link().awaitControlFor(LOOK_NANOS)) {
                if (connection.hasInput() && (!take() || stepReleased) && due[slot]) {
                    LOG.warn("{}: its control code has not yielded and the Environment went on without it; the other "
                            + "robots of this process go on", sims[slot].name());
                    end(slot, "its control code did not yield in time");
                }
            }
            if (due[slot]) { // (with every other late robot that has yielded by now)
                requests.clear();
                add(slot);
                for (int m = l + 1; m < late.size(); m++) {
                    int other = late.get(m);
                    if (other >= 0 && due[other] && sims[other].link().awaitControlFor(0)) {
                        add(other);
                        late.set(m, -1);
                    }
                }
                write();
            }
        }
    }

    private void add(int slot) throws InterruptedException {
        requests.add(slot, sims[slot].request(next[slot]));
        due[slot] = false;
        dueCount--;
    }

    private void write() throws IOException {
        if (requests.count() > 0) {
            connection.write(requests);
            connection.flush();
        }
    }

    /** Reads one frame and applies it; false at the end of the connection (every robot ended). */
    private boolean take() throws IOException {
        Externalizable answer;
        try {
            answer = connection.read(Externalizable.class);
        } catch (EOFException e) {
            for (int slot = 0; slot < sims.length; slot++) {
                if (sims[slot] != null) {
                    end(slot, "the Environment closed the connection");
                }
            }
            return false;
        }
        apply(frame(answer), false);
        return true;
    }

    /** Applies a frame's entries, in order; {@code welcomes}: the frame that answered the hellos (its welcomes read). */
    private void apply(SharedReplies f, boolean welcomes) throws ProtocolException {
        for (int i = 0; i < f.count(); i++) {
            int slot = f.slot(i);
            if (slot < 0 || slot >= sims.length || sims[slot] == null) {
                continue; // (ended here already, or refused: what the Environment still says to it is of no use)
            }
            switch (f.kind(i)) {
                case STEP -> stepDue(slot, f.step(i));
                case RESPONSE -> {
                    sims[slot].apply(f.response(i));
                    stepReleased = true;
                    if (f.step(i) != Protocol.END_OF_SIMULATION) {
                        stepDue(slot, f.step(i));
                    }
                }
                case END -> end(slot, printable(f.end(i).reason()));
                case WELCOME -> {
                    if (!welcomes) {
                        throw new ProtocolException("sent a second welcome for robot " + sims[slot].name());
                    }
                }
            }
        }
    }

    private void stepDue(int slot, long step) {
        next[slot] = step;
        if (!due[slot]) {
            due[slot] = true;
            dueCount++;
        }
    }

    /** Robot {@code slot}'s run is over here. */
    private void end(int slot, String why) {
        HardwareSimulator sim = sims[slot];
        if (due[slot]) {
            due[slot] = false;
            dueCount--;
        }
        sim.endedHere(why);
        sims[slot] = null;
        live--;
    }
}
