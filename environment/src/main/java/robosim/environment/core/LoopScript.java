package robosim.environment.core;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessageFormat;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessagePackException;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.ValueType;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;
import robosim.protocol.ControlScripts;
import robosim.protocol.Limits;
import robosim.protocol.Printable;
import robosim.protocol.ProtocolException;
import robosim.protocol.link.LinkFrames;
import robosim.protocol.link.LinkHello;
import robosim.protocol.link.ScriptProcess;

/**
 * Loop functions that are a Python script ({@code <loopFunctions class="python:FILE">}), served over the loop link
 * (environment/README.md, "The loop link"): at {@link #init} it starts {@code INTERPRETER -m robosim.loop FILE}
 * ({@link ScriptProcess}) and takes its connection on a loopback port the system picks, within {@link #CONNECT_MS};
 * the hello ({@code {"link": "robosim-loop-link", "version": 2, "key", "calls"}}: the calls the script's class defines,
 * by name) is answered with the world's facts ({@code step_ms, seed, parameters, arena, output_directory, objects,
 * lights}). Each call of these loop functions is then one frame to the script, {@code [CALL, STATE]} (CALL one of
 * {@code init, reset, pre_step, post_step, destroy}; STATE the world as it stands, {@link #packState}), answered by
 * requests of the script's ({@code [VERB, ARG...]}: the {@link Experiment}'s changes, each replied
 * {@code ["ok", RESULT]} or {@code ["error", KIND, WHY]}; a move's result is the pose kept, or false) and then its end, {@code ["done", RESULT]} (a post-step's:
 * whether the experiment is finished) or {@code ["failed", TRACEBACK]}. Calls the script does not define are not
 * made. Everything runs on the caller's thread, the simulation loop's; the script's answers are checked as a peer's.
 */
final class LoopScript implements LoopFunctions {
    private static final Logger LOG = LoggerFactory.getLogger(LoopScript.class);
    /** What a hello and a welcome name the link by. */
    static final String NAME = "robosim-loop-link";
    /** The link's version (2: objects out of the world, traces). */
    static final int VERSION = 2;
    private static final LinkHello.Link HELLO = new LinkHello.Link(NAME, "loop link", VERSION, "loop functions",
            List.of("calls"));
    /** How long the script has from its start to its hello, ms (an interpreter's start and the script's imports). */
    static final long CONNECT_MS = 60_000;
    /** How long one call of the script may take, its requests served, ms: then the run ends, the script stopped. */
    static final long CALL_MS = 60_000;
    /** Connections whose hello was refused (not the script's) before the script's own is given up on. */
    static final int MAX_STRANGERS = 8;
    /** The name the script's output is logged under. */
    private static final String SHOWN = "loop";
    /** The longest text argument, characters. */
    private static final int MAX_TEXT = Limits.MAX_UTF_BYTES;
    /** The most arguments a request has. */
    private static final int MAX_ARGS = 5;

    private final String control;
    private final Path script;
    private ScriptProcess process;
    private SocketChannel channel;
    private DataInputStream in;
    private DataOutputStream out;
    /** The calls the script's class defines (its hello's {@code calls}). */
    private final Set<String> calls = new HashSet<>();
    /** What the last post-step answered: the experiment is finished. */
    private boolean finished;
    /** The robots whose names and types the script was sent (robots that join are sent with the next state). */
    private int named;
    /** Each frame to the script, packed here (cleared before each). */
    private final MessageBufferPacker packer = MessagePack.newDefaultBufferPacker();

    /** The script {@code control} names ({@code python:PATH}, {@link ControlScripts}). */
    LoopScript(String control) {
        this.control = control;
        this.script = ControlScripts.script(control);
    }

    /**
     * The link's failure: the script ended, broke the link, made a bad call or did not answer in time; the link is
     * closed and the script stopped before it is thrown (nothing more is asked of it, its destroy neither).
     */
    static class ScriptFailure extends IOException {
        private static final long serialVersionUID = 1L;

        ScriptFailure(String why) {
            super(why, null);
        }

        @Override
        public String toString() {
            return getMessage();
        }
    }

    /** The script's code raised in a call (its traceback logged): the link goes on, so its destroy is still called. */
    static final class CodeFailure extends ScriptFailure {
        private static final long serialVersionUID = 1L;

        CodeFailure(String lastLine) {
            super(lastLine);
        }
    }

    @Override
    public void init(Experiment world) throws Exception {
        if (channel == null) {
            connect(world);
        }
        call("init", world);
    }

    @Override
    public void reset(Experiment world) throws Exception {
        call("reset", world);
    }

    @Override
    public void preStep(Experiment world) throws Exception {
        if (calls.contains("pre_step")) {
            call("pre_step", world);
        }
    }

    @Override
    public void postStep(Experiment world) throws Exception {
        finished = (calls.contains("post_step") || calls.contains("finished")) && call("post_step", world);
    }

    @Override
    public boolean finished(Experiment world) {
        return finished;
    }

    @Override
    public void destroy(Experiment world) throws Exception {
        try {
            if (channel != null && channel.isOpen() && calls.contains("destroy")) {
                call("destroy", world);
            }
        } finally {
            close();
        }
    }

    // ---- the link's start and end ---------------------------------------------------------------------------

    private void connect(Experiment world) throws IOException, InterruptedException {
        String problem = ControlScripts.problem(control);
        if (problem != null) {
            throw new IllegalArgumentException(problem);
        }
        String key = ScriptProcess.newKey();
        try (ServerSocketChannel server = ServerSocketChannel.open()) {
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 1);
            InetSocketAddress at = (InetSocketAddress) server.getLocalAddress();
            // (its output's end, the script's exit, closes the channel: an accept waiting for a script that died ends)
            process = ScriptProcess.start(SHOWN, script, "robosim.loop", at, key, Map.of(), () -> close(server));
            long deadline = System.nanoTime() + CONNECT_MS * 1_000_000;
            String refused = null;
            for (int strangers = 0;; strangers++) {
                SocketChannel peer = accept(server, deadline, refused);
                try {
                    hello(peer, key, world);
                    channel = peer;
                    return;
                } catch (LinkHello.HelloRefused e) {
                    refused = e.getMessage();
                    if (strangers + 1 >= MAX_STRANGERS) {
                        throw new ScriptFailure(process.ended("was not heard", ": " + MAX_STRANGERS
                                + " hellos refused, the last: " + refused));
                    }
                    LOG.warn("loop functions: a hello on their loop link refused: {}", refused);
                }
            }
        } catch (java.nio.channels.ClosedByInterruptException e) {
            close();
            throw new InterruptedException("the run is over");
        } catch (IOException | RuntimeException | InterruptedException e) {
            close();
            throw e;
        }
    }

    private SocketChannel accept(ServerSocketChannel server, long deadline, String refused)
            throws IOException, InterruptedException {
        long left = (deadline - System.nanoTime()) / 1_000_000;
        try {
            if (left <= 0) {
                throw new SocketTimeoutException();
            }
            server.socket().setSoTimeout((int) Math.min(left, Integer.MAX_VALUE));
            return server.socket().accept().getChannel();
        } catch (SocketTimeoutException e) {
            throw new ScriptFailure("its script " + script.getFileName() + " did not connect within " + CONNECT_MS
                    + " ms" + (refused == null ? "" : " (a hello refused: " + refused + ")"));
        } catch (java.nio.channels.ClosedChannelException | java.net.SocketException e) {
            // (closed by the script's end, before or during the accept)
            throw new ScriptFailure(process.ended("exited", " before it connected"
                    + (refused == null ? "" : " (a hello refused: " + refused + ")")));
        }
    }

    /** The script's hello, checked, and the world's facts for it; the connection closed if it fails. */
    private void hello(SocketChannel peer, String key, Experiment world) throws IOException {
        try {
            welcome(peer, key, world);
        } catch (IOException | RuntimeException e) {
            peer.close();
            if (e instanceof LinkHello.HelloRefused r) {
                throw r;
            }
            throw new ScriptFailure("its script " + script.getFileName() + " could not be welcomed: "
                    + LinkFrames.oneLine(String.valueOf(e.getMessage())));
        }
    }

    private void welcome(SocketChannel peer, String key, Experiment world) throws IOException {
        peer.socket().setTcpNoDelay(true);
        in = new DataInputStream(new BufferedInputStream(peer.socket().getInputStream()));
        out = new DataOutputStream(new BufferedOutputStream(peer.socket().getOutputStream()));
        LinkHello hello = LinkHello.read(HELLO, peer.socket(), in, out, key);
        String said = hello.text("calls");
        calls.clear();
        for (String call : (said == null ? "" : said).split(" ")) {
            if (!call.isEmpty()) {
                calls.add(call);
            }
        }
        packer.clear();
        packer.packMapHeader(9);
        packer.packString("link").packString(NAME);
        packer.packString("version").packInt(VERSION);
        packer.packString("step_ms").packLong(world.stepMs());
        packer.packString("seed").packLong(world.seed());
        packer.packString("parameters").packMapHeader(world.parameters().size());
        for (Map.Entry<String, String> p : world.parameters().entrySet()) {
            packer.packString(p.getKey()).packString(p.getValue());
        }
        packer.packString("arena").packArrayHeader(2).packDouble(world.arenaWidthMm())
                .packDouble(world.arenaHeightMm());
        packer.packString("output_directory").packString(world.outputDirectory().toAbsolutePath().toString());
        packer.packString("objects").packArrayHeader(world.objects());
        for (int o = 0; o < world.objects(); o++) {
            packer.packString(world.objectName(o));
        }
        packer.packString("lights").packArrayHeader(world.lights());
        for (int l = 0; l < world.lights(); l++) {
            packer.packString(world.lightName(l));
        }
        LinkFrames.write(out, packer.toByteArray());
        named = 0;
    }

    private void close() {
        try {
            if (channel != null) {
                channel.close();
            }
        } catch (IOException ignored) {
            // (closing is all)
        } finally {
            channel = null;
            if (process != null) {
                process.stop();
                process = null;
            }
        }
    }

    private static void close(ServerSocketChannel server) {
        try {
            server.close();
        } catch (IOException ignored) {
            // (closing is all)
        }
    }

    // ---- a call ---------------------------------------------------------------------------------------------

    /**
     * Calls {@code call} in the script with the world's state, serves its requests until its end, and gives its
     * result: true only for a post-step that said the experiment is finished.
     */
    private boolean call(String call, Experiment world) throws IOException, InterruptedException {
        if (channel == null) {
            throw new ScriptFailure("its script " + script.getFileName() + " is not connected");
        }
        packer.clear();
        packer.packArrayHeader(2).packString(call);
        packState(world);
        java.util.concurrent.ScheduledFuture<?> late = LinkFrames.closeAfter(channel, CALL_MS);
        try {
            LinkFrames.write(out, packer.toByteArray());
            while (true) {
                byte[] frame = LinkFrames.read(in);
                if (frame == null) {
                    throw new IOException("it closed its link");
                }
                Boolean end = answer(frame, world);
                if (end != null) {
                    if (!late.cancel(false)) {
                        throw new IOException("late"); // (its answer came as the deadline closed the link)
                    }
                    return end;
                }
            }
        } catch (CodeFailure e) {
            late.cancel(false);
            throw e;
        } catch (IOException | RuntimeException e) {
            boolean inTime = late.cancel(false);
            boolean interrupted = Thread.currentThread().isInterrupted();
            String why = e instanceof ScriptFailure ? e.getMessage()
                    : !inTime ? "its script " + script.getFileName() + " did not answer " + call + " within " + CALL_MS
                            + " ms"
                    : interrupted ? null
                    : process.ended("ended the link", " in " + call + ": " + LinkFrames.oneLine(e.getMessage()));
            close();
            if (why == null) {
                throw new InterruptedException("the run is over");
            }
            throw new ScriptFailure(why);
        }
    }

    /**
     * The world as the script sees it in a call: {@code {"step", "seed" (the episode's), "names": [[NAME, TYPE]...] (robots not named
     * before), "robots": [[X, Y, HEADING, PRESENT, CARRYING, [LED...]]...], "objects": [[X, Y, HEADING, CARRIER, PRESENT]...],
     * "lights": [ON...]}}.
     */
    private void packState(Experiment world) throws IOException {
        int robots = world.robots();
        packer.packMapHeader(6);
        packer.packString("step").packLong(world.step());
        packer.packString("seed").packLong(world.seed());
        packer.packString("names").packArrayHeader(robots - named);
        for (int r = named; r < robots; r++) {
            packer.packArrayHeader(2).packString(world.robotName(r)).packString(world.robotType(r));
        }
        named = robots;
        packer.packString("robots").packArrayHeader(robots);
        for (int r = 0; r < robots; r++) {
            int[] leds = world.leds(r);
            packer.packArrayHeader(6).packDouble(world.robotXMm(r)).packDouble(world.robotYMm(r))
                    .packDouble(world.robotHeadingDeg(r)).packBoolean(world.present(r)).packInt(world.carrying(r))
                    .packArrayHeader(leds.length);
            for (int led : leds) {
                packer.packInt(led);
            }
        }
        packer.packString("objects").packArrayHeader(world.objects());
        for (int o = 0; o < world.objects(); o++) {
            packer.packArrayHeader(5).packDouble(world.objectXMm(o)).packDouble(world.objectYMm(o))
                    .packDouble(world.objectHeadingDeg(o)).packInt(world.carrier(o)).packBoolean(world.objectPresent(o));
        }
        packer.packString("lights").packArrayHeader(world.lights());
        for (int l = 0; l < world.lights(); l++) {
            packer.packBoolean(world.lightOn(l));
        }
    }

    /** Serves one frame of the script's: its end (the call's result), or a request answered (null). */
    private Boolean answer(byte[] frame, Experiment world) throws IOException {
        String verb;
        try (MessageUnpacker u = MessagePack.newDefaultUnpacker(frame)) {
            if (u.getNextFormat().getValueType() != ValueType.ARRAY) {
                throw new ProtocolException("a request is an array, [VERB, ARG...]");
            }
            int n = u.unpackArrayHeader();
            if (n < 1 || n > MAX_ARGS + 1) {
                throw new ProtocolException("a request of " + n + " items (1 to " + (MAX_ARGS + 1) + ")");
            }
            verb = text(u, "a request's verb", 64);
            Object[] args = new Object[n - 1];
            for (int i = 0; i < args.length; i++) {
                args[i] = value(u);
            }
            if (u.hasNext()) {
                throw new ProtocolException("a frame holds more than its request");
            }
            switch (verb) {
                case "done":
                    if (args.length != 1 || args[0] != null && !(args[0] instanceof Boolean)) {
                        throw new ProtocolException("done takes one result, true, false or nil");
                    }
                    return Boolean.TRUE.equals(args[0]);
                case "failed":
                    if (args.length != 1 || !(args[0] instanceof String account)) {
                        throw new ProtocolException("failed takes one text, its account");
                    }
                    String[] lines = account.strip().split("\n");
                    for (String line : lines) {
                        LOG.warn("loop functions: {}", Printable.of(line, 1000));
                    }
                    throw new CodeFailure(Printable.of(lines[lines.length - 1], 300));
                default:
                    reply(serve(verb, args, world));
                    return null;
            }
        } catch (ScriptFailure e) {
            throw e;
        } catch (IllegalArgumentException | IllegalStateException | IndexOutOfBoundsException e) {
            error("value", e.getMessage());
            return null;
        } catch (ProtocolException | MessagePackException e) {
            String why = e instanceof MessagePackException ? "a frame that is not MessagePack"
                    : LinkFrames.oneLine(e.getMessage());
            error("bad_call", why);
            throw new ScriptFailure("its script " + script.getFileName() + " made a bad call: " + why);
        }
    }

    /** What request {@code verb} does, by the Experiment's calls; its result (null: none). */
    private Object serve(String verb, Object[] a, Experiment world) throws ProtocolException {
        switch (verb) {
            case "move_robot": {
                arity(verb, a, 4);
                int r = index(a[0]);
                return world.moveRobot(r, num(a[1]), num(a[2]), num(a[3]))
                        ? new double[] {world.robotXMm(r), world.robotYMm(r), world.robotHeadingDeg(r)} : false;
            }
            case "move_object": {
                arity(verb, a, 4);
                int o = index(a[0]);
                return world.moveObject(o, num(a[1]), num(a[2]), num(a[3]))
                        ? new double[] {world.objectXMm(o), world.objectYMm(o), world.objectHeadingDeg(o)} : false;
            }
            case "remove_object":
                arity(verb, a, 1);
                world.removeObject(index(a[0]));
                return null;
            case "add_object": {
                arity(verb, a, 4);
                int o = index(a[0]);
                return world.addObject(o, num(a[1]), num(a[2]), num(a[3]))
                        ? new double[] {world.objectXMm(o), world.objectYMm(o), world.objectHeadingDeg(o)} : false;
            }
            case "tell":
                arity(verb, a, 2);
                world.tell(index(a[0]), str(a[1]));
                return null;
            case "floor_colour":
                arity(verb, a, 2);
                return world.floorColour(num(a[0]), num(a[1]));
            case "paint_disc":
                arity(verb, a, 4);
                world.paintDisc(num(a[0]), num(a[1]), num(a[2]), colour(a[3]));
                return null;
            case "paint_rectangle":
                arity(verb, a, 5);
                world.paintRectangle(num(a[0]), num(a[1]), num(a[2]), num(a[3]), colour(a[4]));
                return null;
            case "erase_paint":
                arity(verb, a, 0);
                world.erasePaint();
                return null;
            case "trace":
                arity(verb, a, 4);
                world.trace(str(a[0]), num(a[1]), num(a[2]), colour(a[3]));
                return null;
            case "erase_traces":
                arity(verb, a, 0);
                world.eraseTraces();
                return null;
            case "switch_light":
                arity(verb, a, 2);
                world.switchLight(index(a[0]), bool(a[1]));
                return null;
            case "report":
                arity(verb, a, 2);
                world.report(str(a[0]), num(a[1]));
                return null;
            case "end":
                arity(verb, a, 1);
                world.end(a[0] == null ? null : str(a[0]));
                return null;
            default:
                throw new ProtocolException("no request " + Printable.of(verb, 64));
        }
    }

    private static void arity(String verb, Object[] a, int n) throws ProtocolException {
        if (a.length != n) {
            throw new ProtocolException(verb + " takes " + n + " arguments, got " + a.length);
        }
    }

    private static double num(Object o) throws ProtocolException {
        if (o instanceof Number n) {
            return n.doubleValue();
        }
        throw new ProtocolException("a number expected, got " + kind(o));
    }

    private static String str(Object o) throws ProtocolException {
        if (o instanceof String s) {
            return s;
        }
        throw new ProtocolException("a text expected, got " + kind(o));
    }

    private static boolean bool(Object o) throws ProtocolException {
        if (o instanceof Boolean b) {
            return b;
        }
        throw new ProtocolException("true or false expected, got " + kind(o));
    }

    /** A whole number as an index; one out of any range refused as a value (the Experiment checks the rest). */
    private static int index(Object o) throws ProtocolException {
        if (!(o instanceof Long n)) {
            throw new ProtocolException("an index (a whole number) expected, got " + kind(o));
        }
        if (n < 0 || n > Integer.MAX_VALUE) {
            throw new IndexOutOfBoundsException("no index " + n);
        }
        return n.intValue();
    }

    private static int colour(Object o) throws ProtocolException {
        if (!(o instanceof Long n)) {
            throw new ProtocolException("a colour (a whole number, 0xRRGGBB) expected, got " + kind(o));
        }
        if (n < 0 || n > 0xFFFFFF) {
            throw new IllegalArgumentException("a colour is 0xRRGGBB (0 to 16777215), got " + n);
        }
        return n.intValue();
    }

    private static String kind(Object o) {
        return o == null ? "nil" : o instanceof String ? "a text" : Printable.of(String.valueOf(o), 40);
    }

    /** An argument: nil, a boolean, a whole number (a long), a float (a double) or a text; nothing else. */
    private static Object value(MessageUnpacker u) throws IOException {
        MessageFormat f = u.getNextFormat();
        switch (f.getValueType()) {
            case NIL:
                u.unpackNil();
                return null;
            case BOOLEAN:
                return u.unpackBoolean();
            case INTEGER:
                if (f == MessageFormat.UINT64) {
                    throw new ProtocolException("a whole number out of range");
                }
                return u.unpackLong();
            case FLOAT:
                return u.unpackDouble();
            case STRING:
                return text(u, "a text", MAX_TEXT);
            default:
                throw new ProtocolException("an argument that is a " + f.getValueType().name().toLowerCase());
        }
    }

    private static String text(MessageUnpacker u, String what, int max) throws IOException {
        if (u.getNextFormat().getValueType() != ValueType.STRING) {
            throw new ProtocolException(what + " is not a text");
        }
        int bytes = u.unpackRawStringHeader();
        if (bytes > 4 * max) {
            throw new ProtocolException(what + " of " + bytes + " bytes");
        }
        String s = new String(u.readPayload(bytes), java.nio.charset.StandardCharsets.UTF_8);
        if (s.length() > max) {
            throw new ProtocolException(what + " longer than " + max + " characters");
        }
        return s;
    }

    private void reply(Object result) throws IOException {
        packer.clear();
        packer.packArrayHeader(2).packString("ok");
        if (result == null) {
            packer.packNil();
        } else if (result instanceof Boolean b) {
            packer.packBoolean(b);
        } else if (result instanceof double[] pose) {
            packer.packArrayHeader(pose.length);
            for (double v : pose) {
                packer.packDouble(v);
            }
        } else {
            packer.packInt((Integer) result);
        }
        LinkFrames.write(out, packer.toByteArray());
    }

    private void error(String kind, String why) throws IOException {
        packer.clear();
        packer.packArrayHeader(3).packString("error").packString(kind).packString(LinkFrames.oneLine(why));
        LinkFrames.write(out, packer.toByteArray());
    }
}
