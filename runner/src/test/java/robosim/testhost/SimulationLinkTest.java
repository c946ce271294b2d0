package robosim.testhost;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.Value;
import org.msgpack.value.ValueFactory;
import robosim.api.Robot;
import robosim.api.RobotControl;
import robosim.protocol.ProtocolException;
import robosim.protocol.link.LinkFrames;

/** The simulation link, served on a thread of this JVM to a tester written here with msgpack-core. */
class SimulationLinkTest {
    private static final long WAIT_S = 60;
    private final ExecutorService serving = Executors.newSingleThreadExecutor(r -> new Thread(r, "test-sim-link"));
    private ServerSocket server;
    @TempDir
    Path dir;

    /** Control code that moves, then throws (a bug two steps in). */
    public static final class Careless implements RobotControl {
        @Override
        public void run(Robot robot) throws InterruptedException {
            robot.move(100);
            throw new IllegalStateException("a bug");
        }
    }

    @BeforeEach
    void start() throws Exception {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        Files.writeString(dir.resolve("two.xml"), """
                <environment name="two" timeStepMs="100" seed="1">
                  <param name="speed" value="${speed:400}"/>
                  <arena width="6" height="6"/>
                  <robots>
                    <robot name="mover" type="Scout" control="robosim.examples.BackAndForth" x="1" y="1" heading="0"/>
                    <robot name="careless" type="Scout" control="robosim.testhost.SimulationLinkTest$Careless"
                           x="1" y="4" heading="0"/>
                  </robots>
                </environment>
                """);
    }

    @AfterEach
    void stop() throws Exception {
        serving.shutdownNow();
        server.close();
    }

    private Future<Long> serve(String key) {
        return serving.submit(() -> {
            try (Socket s = server.accept()) {
                SimulationLink link = new SimulationLink(s);
                link.welcome(key);
                return link.serve();
            }
        });
    }

    private static void send(DataOutputStream out, Value... request) throws Exception {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packValue(ValueFactory.newArray(request));
        LinkFrames.write(out, p.toByteArray());
    }

    private static Value s(String text) {
        return ValueFactory.newString(text);
    }

    private static Value n(long v) {
        return ValueFactory.newInteger(v);
    }

    private static Value receive(DataInputStream in) throws Exception {
        try (MessageUnpacker u = MessagePack.newDefaultUnpacker(LinkFrames.read(in))) {
            return u.unpackValue();
        }
    }

    private static void hello(DataOutputStream out, String key) throws Exception {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packMapHeader(3).packString("link").packString(SimulationLink.NAME).packString("version")
                .packInt(SimulationLink.VERSION).packString("key").packString(key);
        LinkFrames.write(out, p.toByteArray());
    }

    private Value start(DataOutputStream out, DataInputStream in, Map<String, Value> fields) throws Exception {
        Map<Value, Value> m = new java.util.LinkedHashMap<>();
        m.put(s("world"), s(dir.resolve("two.xml").toString()));
        fields.forEach((k, v) -> m.put(s(k), v));
        send(out, s("start"), ValueFactory.newMap(m));
        return receive(in);
    }

    @Test
    void aTesterStartsStepsAndAsksAndIsToldOnceOfAFailureWhileTheLinkGoesOn() throws Exception {
        Future<Long> served = serve("k1");
        try (Socket socket = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort())) {
            DataOutputStream out = new DataOutputStream(socket.getOutputStream());
            DataInputStream in = new DataInputStream(socket.getInputStream());
            hello(out, "k1");
            assertEquals("{\"link\":\"robosim-simulation-link\",\"version\":1}", receive(in).toJson());

            assertEquals("[\"ok\",{\"id\":1,\"robots\":[\"mover\",\"careless\"]}]",
                    start(out, in, Map.of("seed", n(3))).toJson());
            send(out, s("pose"), n(1), s("mover"));
            assertEquals("[\"ok\",[1000.0,1000.0,0.0]]", receive(in).toJson());
            send(out, s("run"), n(1), n(20));
            Value failed = receive(in);
            assertEquals("failed", failed.asArrayValue().get(0).asStringValue().asString(), failed.toJson());
            Map<Value, Value> failure = failed.asArrayValue().get(1).asArrayValue().get(0).asMapValue().map();
            assertEquals("careless", failure.get(s("robot")).asStringValue().asString());
            assertEquals("java.lang.IllegalStateException: a bug", failure.get(s("summary")).asStringValue().asString());
            assertTrue(failure.get(s("account")).asStringValue().asString().contains("at robosim.testhost."
                    + "SimulationLinkTest$Careless.run(SimulationLinkTest.java:"), failure.toString());
            assertEquals(20, failed.asArrayValue().get(2).asIntegerValue().asLong());
            send(out, s("run"), n(1), n(5));
            assertEquals("[\"ok\",25]", receive(in).toJson(), "said once: the run goes on");
            send(out, s("pose"), n(1), s("mover"));
            assertTrue(receive(in).asArrayValue().get(1).asArrayValue().get(0).asFloatValue().toDouble() > 1000);

            for (Object[] c : new Object[][] {
                    {new Value[] {s("jump")}, "[\"error\",\"bad_call\",\"no call \\\"jump\\\" without a simulation"},
                    {new Value[] {s("pose"), n(9), s("mover")}, "[\"error\",\"value\",\"no simulation 9 is open\"]"},
                    {new Value[] {s("pose"), n(1), s("nobody")}, "[\"error\",\"value\",\"no robot named \\\"nobody\\\""},
                    {new Value[] {s("pose"), s("1"), s("mover")}, "[\"error\",\"bad_call\",\"ID is a whole number\"]"},
                    {new Value[] {s("run"), n(1), n(0)}, "[\"error\",\"value\",\"run(n) needs n >= 1, got 0\"]"},
                    {new Value[] {s("run"), n(1)}, "[\"error\",\"bad_call\",\"run: [\\\"run\\\", ID, N]\"]"},
                    {new Value[] {s("metric"), n(1), s("speed")}, "[\"error\",\"value\",\"no built-in metric named"},
                    {new Value[] {n(1)}, "[\"error\",\"bad_call\",\"a request is an array [CALL, ARG...]\"]"}}) {
                send(out, (Value[]) c[0]);
                String answer = receive(in).toJson();
                assertTrue(answer.startsWith((String) c[1]), answer);
            }
            assertTrue(start(out, in, Map.of("colour", s("red"))).toJson()
                    .startsWith("[\"error\",\"bad_call\",\"start: no field \\\"colour\\\""));
            assertEquals("[\"error\",\"bad_call\",\"start: history is true or false\"]",
                    start(out, in, Map.of("history", s("no"))).toJson());
            assertTrue(start(out, in, Map.of("params", ValueFactory.newMap(Map.of(s("sped"), s("1"))))).toJson()
                    .contains("sped"), "an unknown parameter is refused, named");
            MessageBufferPacker trailing = MessagePack.newDefaultBufferPacker();
            trailing.packArrayHeader(1).packString("bye").packInt(0);
            LinkFrames.write(out, trailing.toByteArray());
            assertEquals("[\"error\",\"bad_call\",\"a request frame holds more than its array\"]", receive(in).toJson());

            assertEquals("[\"ok\",{\"id\":2,\"robots\":[\"mover\",\"careless\"]}]", start(out, in,
                    Map.of("expect_failure", ValueFactory.newArray(s("careless")))).toJson());
            send(out, s("run"), n(2), n(20));
            assertEquals("[\"ok\",20]", receive(in).toJson(), "an expected failure is no failure of the run");
            send(out, s("failure"), n(2), s("careless"));
            assertTrue(receive(in).toJson().contains("\"summary\":\"java.lang.IllegalStateException: a bug\""));
            send(out, s("close"), n(2));
            assertEquals("[\"ok\",null]", receive(in).toJson());
            send(out, s("steps"), n(2));
            assertEquals("[\"error\",\"value\",\"no simulation 2 is open\"]", receive(in).toJson());

            send(out, s("bye"));
            assertEquals("[\"ok\",null]", receive(in).toJson());
            assertTrue(served.get(WAIT_S, TimeUnit.SECONDS) > 10, "simulation 1, left open, ended with the link");
        }
    }

    private static Value command(double mmPerS, double degPerS) {
        return ValueFactory.newArray(ValueFactory.newFloat(mmPerS), ValueFactory.newFloat(degPerS));
    }

    @Test
    void aRobotDrivenByTheLinkMovesByItsCommandsHeldToItsLimitsAndLogsItsPoses() throws Exception {
        Files.writeString(dir.resolve("driven.xml"), """
                <environment name="driven" timeStepMs="100" seed="1">
                  <param name="speed" value="400"/>
                  <arena width="20" height="6"/>
                  <robots>
                    <robot name="ros" type="Scout" control="ros2" x="1" y="3" heading="0"/>
                    <robot name="mover" type="Scout" control="robosim.examples.BackAndForth" x="1" y="1" heading="0"/>
                  </robots>
                </environment>
                """);
        Future<Long> served = serve("k3");
        try (Socket socket = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort())) {
            DataOutputStream out = new DataOutputStream(socket.getOutputStream());
            DataInputStream in = new DataInputStream(socket.getInputStream());
            hello(out, "k3");
            receive(in);
            Map<Value, Value> fields = new java.util.LinkedHashMap<>();
            fields.put(s("world"), s(dir.resolve("driven.xml").toString()));
            fields.put(s("pose_log"), s(dir.resolve("poses.csv").toString()));
            fields.put(s("history"), ValueFactory.newBoolean(false)); // (as the ROS 2 bridge starts it)
            send(out, s("start"), ValueFactory.newMap(fields));
            assertEquals("[\"ok\",{\"id\":1,\"robots\":[\"ros\",\"mover\"]}]", receive(in).toJson());
            send(out, s("world"), n(1));
            String world = receive(in).toJson();
            assertTrue(world.contains("\"name\":\"ros\",\"type\":\"Scout\",\"driven\":true")
                    && world.contains("\"name\":\"mover\",\"type\":\"Scout\",\"driven\":false"), world);
            for (Object[] c : new Object[][] {
                    {new Value[] {s("run"), n(1), n(3)}, "[\"error\",\"value\",\"run: robots [ros] are driven by the link"},
                    {new Value[] {s("drive"), n(1), ValueFactory.newMap(Map.of(s("mover"), command(1, 0)))},
                        "[\"error\",\"value\",\"drive: mover is not a robot driven by the link"},
                    {new Value[] {s("drive"), n(1), ValueFactory.newMap(Map.of(s("ros"), command(Double.NaN, 0)))},
                        "[\"error\",\"value\",\"drive: ros's command is [MM_PER_S, DEG_PER_S], two finite"},
                    {new Value[] {s("drive"), n(1), s("fast")}, "[\"error\",\"bad_call\",\"drive: the commands are a map"},
                    {new Value[] {s("received"), n(1), s("mover")},
                        "[\"error\",\"value\",\"robot mover's messages are not kept: the simulation was started to keep "
                        + "no history\"]"},
                    {new Value[] {s("contacts"), n(1), s("ros")}, "[\"error\",\"value\",\"robot ros's contacts are not kept"}}) {
                send(out, (Value[]) c[0]);
                String answer = receive(in).toJson();
                assertTrue(answer.startsWith((String) c[1]), answer);
            }
            send(out, s("drive"), n(1), ValueFactory.newMap(Map.of(s("ros"), command(1e9, 0))));
            Value frame = receive(in).asArrayValue().get(1);
            Map<Value, Value> f = frame.asMapValue().map();
            assertEquals(1, f.get(s("step")).asIntegerValue().asLong());
            java.nio.ByteBuffer poses = java.nio.ByteBuffer.wrap(f.get(s("poses")).asBinaryValue().asByteArray())
                    .order(java.nio.ByteOrder.LITTLE_ENDIAN);
            assertEquals(1100, poses.getDouble(0), 1e-6, "a Scout's top speed, 1000 mm/s, for 100 ms");
            assertTrue(f.get(s("robots")).asMapValue().map().containsKey(s("ros")), frame.toJson());
            send(out, s("drive"), n(1), ValueFactory.newMap(Map.of(s("ros"), command(0, -1e9))));
            poses = java.nio.ByteBuffer.wrap(receive(in).asArrayValue().get(1).asMapValue().map().get(s("poses"))
                    .asBinaryValue().asByteArray()).order(java.nio.ByteOrder.LITTLE_ENDIAN);
            assertEquals(1100, poses.getDouble(0), 1e-6, "turning on the spot");
            assertEquals(360 - 30, poses.getDouble(16), 1e-6, "a Scout's top turn, 300 deg/s, for 100 ms");
            send(out, s("close"), n(1));
            assertEquals("[\"ok\",null]", receive(in).toJson());
            java.util.List<String> log = Files.readAllLines(dir.resolve("poses.csv"));
            assertEquals("step,robot,x_m,y_m,heading_deg,state", log.get(0));
            assertTrue(log.contains("1,ros,1.1,3.0,0.0,running") && log.size() == 5, log.toString());
            send(out, s("bye"));
            receive(in);
            served.get(WAIT_S, TimeUnit.SECONDS);
        }
    }

    @Test
    void aHelloWithAnotherKeyIsRefusedAndAnsweredWhy() throws Exception {
        Future<Long> served = serve("k1");
        try (Socket socket = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort())) {
            hello(new DataOutputStream(socket.getOutputStream()), "k2");
            assertEquals("{\"error\":\"a hello with another key than this link was started with\"}",
                    receive(new DataInputStream(socket.getInputStream())).toJson());
            Exception e = assertThrows(ExecutionException.class, () -> served.get(WAIT_S, TimeUnit.SECONDS));
            assertTrue(e.getCause() instanceof ProtocolException, e.toString());
        }
    }

    @Test
    void aHeadlessRunInTheHostGivesItsExitCodeSummaryAndMetrics() throws Exception {
        Future<Long> served = serve("k1");
        try (Socket socket = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort())) {
            DataOutputStream out = new DataOutputStream(socket.getOutputStream());
            DataInputStream in = new DataInputStream(socket.getInputStream());
            hello(out, "k1");
            receive(in);
            Path log = dir.resolve("run.log");
            Path recording = dir.resolve("run.rec");
            Map<Value, Value> m = new java.util.LinkedHashMap<>();
            m.put(s("args"), ValueFactory.newArray(s("--one-jvm"), s("--env"), s(dir.resolve("two.xml").toString()),
                    s("--steps"), s("30"), s("--record"), s(recording.toString())));
            m.put(s("log"), s(log.toString()));
            m.put(s("recording"), s(recording.toString()));
            send(out, s("headless"), ValueFactory.newMap(m));
            Map<Value, Value> answer = receive(in).asArrayValue().get(1).asMapValue().map();
            assertEquals(4, answer.get(s("exit_code")).asIntegerValue().asInt(), "careless's control code threw");
            assertTrue(answer.get(s("broke")).isNilValue());
            assertEquals("30", answer.get(s("summary")).asMapValue().map().get(s("steps")).asStringValue().asString());
            assertTrue(answer.get(s("metrics")).asMapValue().map().get(s("distance_m")).asFloatValue().toDouble() > 0);
            assertTrue(Files.readString(log).contains("robot careless: its control code failed"), "its output logged");
            m.put(s("args"), ValueFactory.newArray(s("--one-jvm"), s("--env"), s(dir.resolve("none.xml").toString()),
                    s("--steps"), s("30")));
            send(out, s("headless"), ValueFactory.newMap(m));
            Map<Value, Value> bad = receive(in).asArrayValue().get(1).asMapValue().map();
            assertEquals(2, bad.get(s("exit_code")).asIntegerValue().asInt());
            assertTrue(bad.get(s("error")).asStringValue().asString().contains("none.xml: file not found"), bad.toString());
            send(out, s("bye"));
            receive(in);
            served.get(WAIT_S, TimeUnit.SECONDS);
        }
    }
}
