package robosim.hardware.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.protocol.ProtocolException;
import robosim.protocol.link.LinkFrames;
import robosim.protocol.link.LinkHello;

/**
 * The robot link against a robot whose every answer is known: the golden transcript (each frame a controller sends,
 * each the link answers, byte for byte: src/test/resources/robot-link/transcript.txt, which a controller in another
 * language replays in its own tests), and the refusals: another version, another robot, garbage, a bad call.
 */
class RobotLinkTest {
    private static final long WAIT_S = 60;
    private static final Path TRANSCRIPT = Path.of("src/test/resources/robot-link/transcript.txt");

    /** A robot whose every answer is fixed, and which keeps what it was told. */
    static final class KnownRobot implements Robot {
        final List<String> told = new ArrayList<>();

        @Override public String name() { return "r1"; }
        @Override public long stepMs() { return 100; }
        @Override public List<String> robotNames() { return List.of("r1", "r2"); }
        @Override public double move(double mm) { told.add("move " + mm); return mm / 2; }
        @Override public double turn(double deg) { told.add("turn " + deg); return deg; }
        @Override public void setVelocity(double v) { told.add("velocity " + v); }
        @Override public double velocity() { return 300; }
        @Override public void setRotVelocity(double v) { told.add("rot " + v); }
        @Override public double rotVelocity() { return 45; }
        @Override public String tag() { return ""; }
        @Override public void sleep(long ms) throws InterruptedException {
            if (ms > 1_000_000) {
                throw new InterruptedException("the simulation is over");
            }
            told.add("sleep " + ms);
        }
        @Override public double[] sonarRanges() { return new double[] {1000.5, 250}; }
        @Override public double[] sonarAnglesDeg() { return new double[] {90, -90}; }
        @Override public List<String> sensorNames() { return List.of("bump"); }
        @Override public double[] sensor(String name) {
            if (!name.equals("bump")) {
                throw new IllegalArgumentException("no sensor named " + name + " (it has: bump)");
            }
            return new double[] {0};
        }
        @Override public double xMm() { return 1500; }
        @Override public double yMm() { return 2500; }
        @Override public double headingDeg() { return 90; }
        @Override public String lastContact() { return "wall"; }
        @Override public void send(String to, String text) {
            if (text.length() > 10) {
                throw new IllegalArgumentException("text of " + text.length() + " characters, at most 10");
            }
            told.add("send " + to + " " + text);
        }
        @Override public void broadcast(String text) { told.add("broadcast " + text); }
        @Override public Message receive() { return new Message("r2", "hi"); }
        @Override public Message waitForMessage(long ms) { return null; }
        @Override public long seed() { return 42; }
        @Override public String parameter(String name, String fallback) { return name.equals("speed") ? "900" : fallback; }
        @Override public void report(String name, double value) { told.add("report " + name + " " + value); }
    }

    /** A link serving {@code robot} on a loopback port, and a connection to it. */
    private record Served(Socket client, CompletableFuture<Throwable> end) implements AutoCloseable {
        static Served of(Robot robot) throws IOException {
            return of(robot, null);
        }

        /** A link whose hello must carry {@code key} (null: none). */
        static Served of(Robot robot, String key) throws IOException {
            ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
            CompletableFuture<Throwable> end = new CompletableFuture<>();
            Thread t = new Thread(() -> {
                try (server) {
                    RobotLink.serve(server.accept(), robot, key);
                    end.complete(null);
                } catch (Throwable e) {
                    end.complete(e);
                }
            }, "link-under-test");
            t.setDaemon(true);
            t.start();
            return new Served(new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort()), end);
        }

        byte[] exchange(byte[] frame) throws IOException {
            LinkFrames.write(new DataOutputStream(client.getOutputStream()), frame);
            return LinkFrames.read(new DataInputStream(new BufferedInputStream(client.getInputStream(), 1)));
        }

        Throwable awaitEnd() throws Exception {
            return end.get(WAIT_S, TimeUnit.SECONDS);
        }

        @Override
        public void close() throws IOException {
            client.close();
        }
    }

    @Test
    void theGoldenTranscriptIsWhatTheLinkAnswersByteForByte() throws Exception {
        List<String> lines = Files.readAllLines(TRANSCRIPT, StandardCharsets.UTF_8);
        KnownRobot robot = new KnownRobot();
        int exchanges = 0;
        try (Served link = Served.of(robot)) {
            for (int i = 0; i < lines.size(); i++) {
                String line = lines.get(i);
                if (!line.startsWith("> ")) {
                    continue;
                }
                String answer = lines.get(i + 1);
                assertTrue(answer.startsWith("< "), "line " + (i + 2) + ": the link's answer follows each frame sent");
                byte[] got = link.exchange(hex(line));
                assertEquals(answer.substring(2, answer.indexOf(' ', 2) < 0 ? answer.length() : answer.indexOf(' ', 2)),
                        HexFormat.of().formatHex(got), "the answer to line " + (i + 1) + ": " + line);
                exchanges++;
            }
            assertEquals(null, link.awaitEnd(), "the transcript ends with a bye: the link ends as control code that returned");
        }
        assertTrue(exchanges >= 20, "every call is in the transcript: " + exchanges);
        assertEquals(List.of("move 2000.0", "turn -90.0", "velocity 300.0", "rot 45.0", "sleep 100", "send r2 hello",
                "broadcast all", "report found 3.0"), robot.told);
    }

    /** The frame of a transcript line ({@code > HEX  # what}). */
    private static byte[] hex(String line) {
        String rest = line.substring(2);
        int space = rest.indexOf(' ');
        return HexFormat.of().parseHex(space < 0 ? rest : rest.substring(0, space));
    }

    private static byte[] hello(String link, int version, String robot) throws IOException {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packMapHeader(3).packString("link").packString(link).packString("version").packInt(version)
                .packString("robot").packString(robot);
        return p.toByteArray();
    }

    private static String error(byte[] answer) throws IOException {
        var u = MessagePack.newDefaultUnpacker(answer);
        var value = u.unpackValue();
        return value.isMapValue() ? value.asMapValue().map().values().iterator().next().toString() : value.toString();
    }

    @Test
    void anotherVersionAnotherRobotOrAStrangerIsRefusedInOneLineOnBothSides() throws Exception {
        try (Served link = Served.of(new KnownRobot())) {
            assertEquals("robot link version 2 is not supported (this simulator speaks 1)",
                    error(link.exchange(hello(RobotLink.NAME, 2, "r1"))));
            Throwable end = link.awaitEnd();
            assertInstanceOf(ProtocolException.class, end);
            assertEquals("robot link version 2 is not supported (this simulator speaks 1)", end.getMessage());
        }
        try (Served link = Served.of(new KnownRobot())) {
            assertEquals("this link serves robot r1, not \"r9\"", error(link.exchange(hello(RobotLink.NAME, 1, "r9"))));
        }
        try (Served link = Served.of(new KnownRobot())) {
            assertTrue(error(link.exchange("GET / HTTP/1.1\r\n".getBytes(StandardCharsets.US_ASCII)))
                    .startsWith("a hello is a map"));
        }
        for (byte[] raw : List.of("GET / HTTP/1.1\r\nHost: x\r\n\r\n".getBytes(StandardCharsets.US_ASCII),
                new byte[] {(byte) 0x80, 0, 0, 0}, new byte[] {0, 0, 0, 0})) { // (no frame: HTTP, 2^31, 0 bytes)
            try (Served link = Served.of(new KnownRobot())) {
                link.client().getOutputStream().write(raw);
                byte[] answer = LinkFrames.read(new DataInputStream(new BufferedInputStream(
                        link.client().getInputStream(), 1)));
                assertTrue(error(answer).startsWith("not a robot link's hello frame: a frame of "), error(answer));
                assertInstanceOf(ProtocolException.class, link.awaitEnd());
            }
        }
        try (Served link = Served.of(new KnownRobot())) {
            MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
            p.packMapHeader(2).packString("link").packString(RobotLink.NAME).packString("robot").packInt(7);
            assertEquals("robot is not a text", error(link.exchange(p.toByteArray())));
        }
        try (Served link = Served.of(new KnownRobot())) {
            MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
            p.packMapHeader(2).packString("link").packString(RobotLink.NAME).packString("robot").packString("r1");
            assertEquals("a hello without its version (this simulator speaks 1)", error(link.exchange(p.toByteArray())));
        }
        try (Served link = Served.of(new KnownRobot())) {
            assertEquals("robot is longer than " + LinkHello.MAX_TEXT + " characters",
                    error(link.exchange(hello(RobotLink.NAME, 1, "r".repeat(LinkHello.MAX_TEXT + 1)))));
        }
        try (Served link = Served.of(new KnownRobot())) {
            MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
            p.packMapHeader(LinkHello.MAX_FIELDS + 1);
            for (int f = 0; f <= LinkHello.MAX_FIELDS; f++) {
                p.packString("f" + f).packInt(f);
            }
            assertTrue(error(link.exchange(p.toByteArray())).startsWith("a hello of " + (LinkHello.MAX_FIELDS + 1)
                    + " fields"));
        }
    }

    @Test
    void aLinkStartedWithAKeyServesOnlyAHelloThatCarriesIt() throws Exception {
        try (Served link = Served.of(new KnownRobot(), "s3cret")) {
            assertEquals("a hello without the key this link was started with",
                    error(link.exchange(hello(RobotLink.NAME, 1, "r1"))));
            assertInstanceOf(LinkHello.HelloRefused.class, link.awaitEnd());
        }
        try (Served link = Served.of(new KnownRobot(), "s3cret")) {
            assertEquals("a hello with another key than this link was started with",
                    error(link.exchange(keyed("guess"))));
        }
        try (Served link = Served.of(new KnownRobot(), "s3cret")) {
            var welcome = MessagePack.newDefaultUnpacker(link.exchange(keyed("s3cret"))).unpackValue();
            assertEquals("r1", welcome.asMapValue().map().get(org.msgpack.value.ValueFactory.newString("robot"))
                    .toString());
        }
    }

    private static byte[] keyed(String key) throws IOException {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packMapHeader(4).packString("link").packString(RobotLink.NAME).packString("version").packInt(1)
                .packString("robot").packString("r1").packString("key").packString(key);
        return p.toByteArray();
    }

    @Test
    void aBadCallIsAnsweredAndEndsTheLinkAValueTheRobotRefusesDoesNot() throws Exception {
        try (Served link = Served.of(new KnownRobot())) {
            link.exchange(hello(RobotLink.NAME, 1, "r1"));
            MessageBufferPacker send = MessagePack.newDefaultBufferPacker();
            send.packArrayHeader(3).packString("send").packString("r2").packString("a text too long");
            assertEquals("[\"error\",\"value\",\"text of 15 characters, at most 10\"]",
                    MessagePack.newDefaultUnpacker(link.exchange(send.toByteArray())).unpackValue().toJson());
            MessageBufferPacker move = MessagePack.newDefaultBufferPacker();
            move.packArrayHeader(2).packString("move").packString("far");
            assertEquals("[\"error\",\"bad_call\",\"move: argument 1 is a string, not a number\"]",
                    MessagePack.newDefaultUnpacker(link.exchange(move.toByteArray())).unpackValue().toJson());
            assertInstanceOf(ProtocolException.class, link.awaitEnd());
        }
    }

    /** A {@link LinkedControl} robot (a {@link KnownRobot}) waiting on a loopback port, run on a thread of its own. */
    private record Linked(java.nio.channels.ServerSocketChannel listening, int port, Thread control,
            CompletableFuture<Throwable> end) {
        static Linked start() throws IOException {
            java.nio.channels.ServerSocketChannel listening = java.nio.channels.ServerSocketChannel.open();
            listening.bind(new java.net.InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 1);
            int port = ((java.net.InetSocketAddress) listening.getLocalAddress()).getPort();
            CompletableFuture<Throwable> end = new CompletableFuture<>();
            Thread control = new Thread(() -> {
                try {
                    new LinkedControl(listening).run(new KnownRobot());
                    end.complete(null);
                } catch (Throwable e) {
                    end.complete(e);
                }
            }, "linked-control-under-test");
            control.setDaemon(true);
            control.start();
            return new Linked(listening, port, control, end);
        }
    }

    @Test
    void aLinkedRobotsPortRefusesStrangersAndWaitsOnForItsController() throws Exception {
        Linked linked = Linked.start();
        int port = linked.port();
        CompletableFuture<Throwable> end = linked.end();
        try (Socket stranger = new Socket(InetAddress.getLoopbackAddress(), port)) {
            stranger.getOutputStream().write("GET / HTTP/1.1\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
            byte[] answer = LinkFrames.read(new DataInputStream(new BufferedInputStream(stranger.getInputStream(), 1)));
            assertTrue(error(answer).startsWith("not a robot link's hello frame"), error(answer));
        }
        try (Socket controller = new Socket(InetAddress.getLoopbackAddress(), port)) {
            DataInputStream in = new DataInputStream(new BufferedInputStream(controller.getInputStream(), 1));
            LinkFrames.write(new DataOutputStream(controller.getOutputStream()), hello(RobotLink.NAME, 1, "r1"));
            assertTrue(MessagePack.newDefaultUnpacker(LinkFrames.read(in)).unpackValue().toJson()
                    .contains("\"robot\":\"r1\""), "the controller welcomed after the stranger");
            MessageBufferPacker bye = MessagePack.newDefaultBufferPacker();
            bye.packArrayHeader(1).packString("bye");
            LinkFrames.write(new DataOutputStream(controller.getOutputStream()), bye.toByteArray());
            assertEquals(null, end.get(WAIT_S, TimeUnit.SECONDS), "its control code returned at the bye");
        }
    }

    @Test
    void theEndOfTheSimulationEndsALinkedRobotsWaitForItsController() throws Exception {
        Linked linked = Linked.start();
        int port = linked.port();
        CompletableFuture<Throwable> end = linked.end();
        Thread control = linked.control();
        java.nio.channels.ServerSocketChannel listening = linked.listening();
        try (Socket silent = new Socket(InetAddress.getLoopbackAddress(), port)) { // (a stranger that says nothing)
            control.interrupt(); // (the simulation's end, as the Hardware Simulator tells control code)
            assertInstanceOf(InterruptedException.class, end.get(WAIT_S, TimeUnit.SECONDS));
        }
        assertTrue(!listening.isOpen(), "its port closed");
    }

    @Test
    void aFrameOverTheLimitIsRefusedBeforeItIsRead() throws Exception {
        try (Served link = Served.of(new KnownRobot())) {
            new DataOutputStream(link.client().getOutputStream()).writeInt(LinkFrames.MAX_BYTES + 1);
            Throwable end = link.awaitEnd();
            assertInstanceOf(ProtocolException.class, end);
            assertEquals("not a robot link's hello frame: a frame of " + (LinkFrames.MAX_BYTES + 1) + " bytes (1 to "
                    + LinkFrames.MAX_BYTES + ")", end.getMessage());
        }
    }

    @Test
    void theEndOfTheSimulationEndsTheLinkAndAFailureIsTheControllersOwnAccount() throws Exception {
        try (Served link = Served.of(new KnownRobot())) {
            link.exchange(hello(RobotLink.NAME, 1, "r1"));
            MessageBufferPacker sleep = MessagePack.newDefaultBufferPacker();
            sleep.packArrayHeader(2).packString("sleep").packLong(2_000_000);
            assertEquals("[\"error\",\"over\",\"the simulation is over\"]",
                    MessagePack.newDefaultUnpacker(link.exchange(sleep.toByteArray())).unpackValue().toJson());
            assertInstanceOf(InterruptedException.class, link.awaitEnd());
        }
        try (Served link = Served.of(new KnownRobot())) {
            link.exchange(hello(RobotLink.NAME, 1, "r1"));
            MessageBufferPacker failed = MessagePack.newDefaultBufferPacker();
            failed.packArrayHeader(2).packString("failed").packString("Traceback ...\nZeroDivisionError: division by zero");
            link.exchange(failed.toByteArray());
            Throwable end = link.awaitEnd();
            assertInstanceOf(RobotLink.ControllerFailure.class, end);
            assertEquals("ZeroDivisionError: division by zero", end.getMessage(), "its last line (the whole was logged)");
            assertEquals("ZeroDivisionError: division by zero", end.toString(), "no Java class: the failure is its own");
        }
    }
}
