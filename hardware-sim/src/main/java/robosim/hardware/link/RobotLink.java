package robosim.hardware.link;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.util.List;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessageFormat;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessagePackException;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.ValueType;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.protocol.Limits;
import robosim.protocol.Printable;
import robosim.protocol.ProtocolException;
import robosim.protocol.link.LinkFrames;
import robosim.protocol.link.LinkHello;

/**
 * The robot link: one robot's API served to control code in another process, in any language, over a socket of
 * length-prefixed MessagePack frames ({@link LinkFrames}; hardware-sim/README.md, "The robot link"). The controller
 * says hello ({@code {"link": "robosim-robot-link", "version": 1, "robot": NAME}}) within
 * {@link LinkHello#DEADLINE_MS} ({@link LinkHello}); the link answers with the robot's facts ({@code {"link", "version", "robot", "step_ms",
 * "robots", "seed"}}) or {@code {"error": WHY}} and closes. Then each call of the robot API is one request, an array
 * {@code [CALL, ARG...]}, and one reply, {@code ["ok", RESULT]} or {@code ["error", KIND, WHY]}: the Hardware
 * Simulator keeps the time, so {@code ["move", 2000]} is answered once the robot has moved (or touched something),
 * however many steps that takes. Kinds: {@code value} (the robot refused a value: the controller raises, the link
 * goes on), {@code bad_call} (no such call, or arguments not of its kinds: the link ends), {@code over} (the simulation
 * is over: the link ends). {@code ["bye"]} ends the link as control code that returned does; {@code ["failed", TEXT]}
 * as control code that threw ({@link ControllerFailure}).
 */
public final class RobotLink {
    private static final Logger LOG = LoggerFactory.getLogger(RobotLink.class);
    /** What a hello and a welcome name the link by. */
    public static final String NAME = "robosim-robot-link";
    /** The link's version: a controller of another is refused with both in one line. */
    public static final int VERSION = 1;
    /** What its hello must be: the link's name and version, and the robot's name. */
    private static final LinkHello.Link HELLO = new LinkHello.Link(NAME, "robot link", VERSION, "controller",
            List.of("robot"));
    /** The longest text a robot name or a call's name may have, characters. */
    private static final int MAX_NAME = 256;
    /** The longest text argument, characters: a message's text (at most the wire's string, in bytes) fits. */
    private static final int MAX_TEXT = Limits.MAX_UTF_BYTES;

    private final Socket socket;
    private final Robot robot;
    private final DataInputStream in;
    private final DataOutputStream out;
    /** Calls come so far, a bye or a failure among them (for the line at the link's end). */
    private long served;
    /** Each call's reply, packed here (cleared before each): one buffer for the link's life, not one a call. */
    private final MessageBufferPacker reply = MessagePack.newDefaultBufferPacker();

    private RobotLink(Socket socket, Robot robot) throws IOException {
        this.socket = socket;
        this.robot = robot;
        this.in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
        this.out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
    }

    /**
     * A controller that reported its control code failed: its message the account's last line (in Python, the
     * exception's: {@code ZeroDivisionError: division by zero}); the whole account (a traceback) was logged once
     * with the robot's name when it came. Each line is made safe for a log line ({@link Printable}), the account
     * cut at {@link #MAX_ACCOUNT} characters.
     */
    public static final class ControllerFailure extends RuntimeException {
        private static final long serialVersionUID = 1L;
        /** The longest account kept, characters. */
        static final int MAX_ACCOUNT = 4000;
        /** The whole account, its lines as logged (without the robot's name). */
        private final String account;

        ControllerFailure(String lastLine, String account) {
            super(lastLine, null, false, false);
            this.account = account;
        }

        /** The controller's whole account of its failure (a traceback), each line made safe as it was logged. */
        public String account() {
            return account;
        }

        /** Its message alone (what failed is the controller's, not a Java class). */
        @Override
        public String toString() {
            return getMessage();
        }
    }

    /**
     * Serves {@code robot} to the controller at the other end of {@code socket} until it says bye (returns), it
     * reports a failure ({@link ControllerFailure}), or the simulation is over (InterruptedException); closes the
     * socket at the end.
     *
     * @throws ProtocolException a hello that is late, not a robot link's, of another version or another robot; a
     *     frame or a call that is not one; the connection ended by the controller
     */
    public static void serve(Socket socket, Robot robot) throws IOException, InterruptedException {
        serve(socket, robot, null);
    }

    /**
     * As {@link #serve(Socket, Robot)}, for a controller this simulator started: its hello must carry {@code key}
     * (a secret it was given) as {@code "key"}, or it is refused ({@link LinkHello.HelloRefused}) before anything is
     * served.
     */
    public static void serve(Socket socket, Robot robot, String key) throws IOException, InterruptedException {
        try (socket) {
            welcomed(socket, robot, key).serve();
        }
    }

    /**
     * The link of the controller at the other end of {@code socket}, its hello read and answered (as
     * {@link #serve(Socket, Robot, String)} does first); nothing served yet.
     *
     * @throws LinkHello.HelloRefused its hello was refused (answered why where it came)
     */
    static RobotLink welcomed(Socket socket, Robot robot, String key) throws IOException {
        if (!socket.getInetAddress().isLoopbackAddress()) { // (keys for a link beyond loopback: not yet)
            throw new ProtocolException("the robot link takes loopback connections only, not "
                    + socket.getInetAddress().getHostAddress());
        }
        socket.setTcpNoDelay(true); // (a reply is one write; with a request in flight it must not wait)
        RobotLink link = new RobotLink(socket, robot);
        link.welcome(key);
        return link;
    }

    /** Serves the welcomed controller's calls until it says bye, fails, or the simulation is over; closes its socket. */
    void serve() throws IOException, InterruptedException {
        try (socket) {
            calls();
        } finally {
            LOG.info("{}: its controller made {} calls over the robot link", robot.name(), served);
        }
    }

    private void welcome(String wanted) throws IOException {
        LinkHello hello = LinkHello.read(HELLO, socket, in, out, wanted);
        String robotName = hello.text("robot");
        if (!robot.name().equals(robotName)) {
            throw hello.refuse("this link serves robot " + robot.name() + ", not \"" + Printable.of(robotName, 40)
                    + "\"");
        }
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packMapHeader(6);
        p.packString("link").packString(NAME);
        p.packString("version").packInt(VERSION);
        p.packString("robot").packString(robot.name());
        p.packString("step_ms").packLong(robot.stepMs());
        p.packString("robots");
        strings(p, robot.robotNames());
        p.packString("seed").packLong(robot.seed());
        LinkFrames.write(out, p.toByteArray());
    }

    /**
     * The controller's failure with account {@code text}, which is logged once, each line made safe for a log and
     * begun with the robot's name and {@code "| "} (no line of it can pass for one of the log's own).
     */
    private ControllerFailure failure(String text) {
        String account = text.strip();
        List<String> lines = account.substring(0, Math.min(account.length(), ControllerFailure.MAX_ACCOUNT)).lines()
                .map(Printable::of).toList();
        String last = lines.isEmpty() ? "(no account)" : lines.get(lines.size() - 1).strip();
        String name = robot.name();
        LOG.error("{}: its controller failed:\n{}", name, String.join("\n", lines.stream().map(l -> name + "| " + l)
                .toList()));
        return new ControllerFailure(last.isEmpty() ? "(no account)" : last, String.join("\n", lines));
    }

    private void calls() throws IOException, InterruptedException {
        while (true) {
            byte[] frame = LinkFrames.read(in);
            if (frame == null) {
                throw new ProtocolException("the controller closed the link without a bye");
            }
            served++;
            reply.clear();
            String call;
            try (MessageUnpacker u = MessagePack.newDefaultUnpacker(frame)) {
                if (u.getNextFormat().getValueType() != ValueType.ARRAY) {
                    throw badCall("a call is an array: [CALL, ARG...]");
                }
                int size = u.unpackArrayHeader();
                if (size < 1) {
                    throw badCall("a call is an array: [CALL, ARG...]");
                }
                if (u.getNextFormat().getValueType() != ValueType.STRING) {
                    throw badCall("a call's name is a text");
                }
                call = u.unpackString();
                if (call.length() > MAX_NAME) {
                    throw badCall("a call's name of " + call.length() + " characters");
                }
                Arguments args = new Arguments(call, u, size - 1);
                switch (call) {
                    case "bye" -> {
                        args.none();
                        reply.packArrayHeader(2).packString("ok").packNil();
                        reply(reply);
                        return;
                    }
                    case "failed" -> {
                        String text = args.text();
                        reply.packArrayHeader(2).packString("ok").packNil();
                        reply(reply);
                        throw failure(text);
                    }
                    default -> {
                        reply.packArrayHeader(2).packString("ok");
                        RobotCalls.call(robot, call, args, reply);
                    }
                }
                if (u.hasNext()) {
                    throw badCall(call + ": a call's frame holds more than its array");
                }
            } catch (MessagePackException e) {
                throw badCall("a call that is not MessagePack: " + LinkFrames.oneLine(e.getMessage()));
            } catch (IllegalArgumentException | UnsupportedOperationException e) { // (a value or a device it has not)
                reply.clear();
                reply.packArrayHeader(3).packString("error").packString("value").packString(LinkFrames.oneLine(e.getMessage()));
            } catch (InterruptedException e) {
                // (the simulation's end interrupts this thread: cleared, so the reply is written on a socket that an
                // interrupt would close, then the end goes on)
                Thread.interrupted();
                try {
                    reply.clear();
                    reply.packArrayHeader(3).packString("error").packString("over").packString("the simulation is over");
                    reply(reply);
                } catch (IOException gone) {
                    // (the controller may be gone too)
                }
                throw e;
            }
            reply(reply);
        }
    }

    private void reply(MessageBufferPacker reply) throws IOException {
        LinkFrames.write(out, reply.toByteArray());
    }

    /** Answers {@code ["error", "bad_call", why]} (best effort) and makes the refusal. */
    ProtocolException badCall(String why) {
        try {
            MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
            p.packArrayHeader(3).packString("error").packString("bad_call").packString(why);
            LinkFrames.write(out, p.toByteArray());
        } catch (IOException gone) {
            // (the refusal stands whether the controller hears it or not)
        }
        return new ProtocolException(why);
    }

    /** A call's arguments, read in order as the call's kinds say; a wrong count or kind is a bad call. */
    final class Arguments {
        private final String call;
        private final MessageUnpacker u;
        private final int count;
        private int read;

        Arguments(String call, MessageUnpacker u, int count) {
            this.call = call;
            this.u = u;
            this.count = count;
        }

        private void next(String kind) throws ProtocolException {
            if (read >= count) {
                throw badCall(call + ": " + count + " argument(s), it takes more (" + kind + " next)");
            }
            read++;
        }

        /** The end of the arguments: no more than were read. */
        void none() throws ProtocolException {
            if (read != count) {
                throw badCall(call + ": " + count + " argument(s), it takes " + read);
            }
        }

        double number() throws IOException {
            next("a number");
            MessageFormat f = u.getNextFormat();
            if (f.getValueType() == ValueType.FLOAT) {
                return u.unpackDouble();
            }
            if (f.getValueType() == ValueType.INTEGER) {
                return u.unpackBigInteger().doubleValue(); // (a uint64 over a long's range is a number too)
            }
            throw badCall(call + ": argument " + read + " is a " + f.getValueType().name().toLowerCase()
                    + ", not a number");
        }

        long whole() throws IOException {
            next("a whole number");
            if (u.getNextFormat().getValueType() != ValueType.INTEGER) {
                throw badCall(call + ": argument " + read + " is not a whole number");
            }
            java.math.BigInteger n = u.unpackBigInteger();
            if (n.bitLength() > 63) {
                throw badCall(call + ": argument " + read + " is out of range");
            }
            return n.longValue();
        }

        String text() throws IOException {
            next("a text");
            if (u.getNextFormat().getValueType() != ValueType.STRING) {
                throw badCall(call + ": argument " + read + " is not a text");
            }
            String s = u.unpackString();
            if (s.length() > MAX_TEXT) {
                throw badCall(call + ": argument " + read + " is a text of " + s.length() + " characters, at most "
                        + MAX_TEXT);
            }
            return s;
        }

        /** A list of numbers, at most {@link robosim.protocol.Limits#MAX_SENSOR_VALUES}. */
        double[] numbers() throws IOException {
            next("a list of numbers");
            if (u.getNextFormat().getValueType() != ValueType.ARRAY) {
                throw badCall(call + ": argument " + read + " is not a list of numbers");
            }
            int n = u.unpackArrayHeader();
            if (n > robosim.protocol.Limits.MAX_SENSOR_VALUES) {
                throw badCall(call + ": argument " + read + " is a list of " + n + " values, at most "
                        + robosim.protocol.Limits.MAX_SENSOR_VALUES);
            }
            double[] out = new double[n];
            for (int k = 0; k < n; k++) {
                MessageFormat f = u.getNextFormat();
                if (f.getValueType() == ValueType.FLOAT) {
                    out[k] = u.unpackDouble();
                } else if (f.getValueType() == ValueType.INTEGER) {
                    out[k] = u.unpackBigInteger().doubleValue();
                } else {
                    throw badCall(call + ": argument " + read + " holds a " + f.getValueType().name().toLowerCase()
                            + ", not a number");
                }
            }
            return out;
        }

        /**
         * A colour: a whole number {@code 0xRRGGBB}, or a text {@link robosim.api.Colours#parse} reads (a name,
         * {@code #rrggbb}, {@code r,g,b}); a text that is none is the robot's to refuse (IllegalArgumentException).
         */
        int colour() throws IOException {
            if (peek() == ValueType.STRING) {
                return robosim.api.Colours.parse(text());
            }
            long c = whole();
            if (c < 0 || c > 0xFFFFFF) {
                throw new IllegalArgumentException("a colour is 0 to 0xFFFFFF, got " + c);
            }
            return (int) c;
        }

        /** A bad call of this call's: answered, and the link's end. */
        ProtocolException bad(String why) {
            return badCall(why);
        }

        /** The next argument's kind, or null after the last. */
        ValueType peek() throws IOException {
            return read < count ? u.getNextFormat().getValueType() : null;
        }
    }

    static void strings(MessageBufferPacker p, List<String> list) throws IOException {
        p.packArrayHeader(list.size());
        for (String s : list) {
            p.packString(s);
        }
    }


    /** What a robot's message is on the link: {@code [from, text]}, or nil. */
    static void message(MessageBufferPacker p, Message m) throws IOException {
        if (m == null) {
            p.packNil();
        } else {
            p.packArrayHeader(2).packString(m.from()).packString(m.text());
        }
    }

    /** The doubles as an array of float64s, or nil. */
    static void numbers(MessageBufferPacker p, double[] values) throws IOException {
        if (values == null) {
            p.packNil();
            return;
        }
        p.packArrayHeader(values.length);
        for (double v : values) {
            p.packDouble(v);
        }
    }
}
