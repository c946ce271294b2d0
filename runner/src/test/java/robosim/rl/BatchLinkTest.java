package robosim.rl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.Value;
import robosim.protocol.link.LinkFrames;
import robosim.protocol.ProtocolException;

/** The learning link, served on a thread of this JVM to a learner written here with msgpack-core. */
class BatchLinkTest {
    private static final long WAIT_S = 60;
    private final ExecutorService serving = Executors.newSingleThreadExecutor(r -> new Thread(r, "test-batch-link"));
    private BatchWorlds batch;
    private ServerSocket server;

    @BeforeEach
    void start() throws Exception {
        batch = new BatchWorlds(BatchWorldsTest.world(), 2, new BatchWorlds.Settings(1, 0, false, 0.5, 2));
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
    }

    @AfterEach
    void stop() throws Exception {
        serving.shutdownNow();
        server.close();
        batch.close();
    }

    /** Serves the next connection: its hello (with {@code key}), then its requests; the steps served. */
    private Future<Long> serve(String key) {
        return serving.submit(() -> {
            try (Socket s = server.accept()) {
                BatchLink link = new BatchLink(s, batch, null);
                link.welcome(key);
                return link.serve();
            }
        });
    }

    private static void send(DataOutputStream out, Object... request) throws Exception {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packValue(org.msgpack.value.ValueFactory.newArray(java.util.Arrays.stream(request).map(BatchLinkTest::value)
                .toList()));
        LinkFrames.write(out, p.toByteArray());
    }

    private static Value value(Object o) {
        return o instanceof String s ? org.msgpack.value.ValueFactory.newString(s)
                : o instanceof byte[] b ? org.msgpack.value.ValueFactory.newBinary(b)
                : o instanceof Value v ? v : org.msgpack.value.ValueFactory.newNil();
    }

    private static Value receive(DataInputStream in) throws Exception {
        try (MessageUnpacker u = MessagePack.newDefaultUnpacker(LinkFrames.read(in))) {
            return u.unpackValue();
        }
    }

    private static void hello(DataOutputStream out, String key) throws Exception {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packMapHeader(3).packString("link").packString(BatchLink.NAME).packString("version").packInt(BatchLink.VERSION)
                .packString("key").packString(key);
        LinkFrames.write(out, p.toByteArray());
    }

    @Test
    void aLearnerStepsTheWorldsAndIsToldWhatIsWrongWithABadRequestWhileTheLinkGoesOn() throws Exception {
        Future<Long> served = serve("k1");
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort())) {
            DataOutputStream out = new DataOutputStream(s.getOutputStream());
            DataInputStream in = new DataInputStream(s.getInputStream());
            hello(out, "k1");
            Value welcome = receive(in);
            assertEquals("[\"a\",\"b\",\"c\"]", welcome.asMapValue().map().get(
                    org.msgpack.value.ValueFactory.newString("robots")).toJson());
            assertEquals(2, welcome.asMapValue().map().get(org.msgpack.value.ValueFactory.newString("worlds")).asIntegerValue()
                    .asInt());

            send(out, "step", new byte[2 * 3 * 2 * 4], null);
            Value ok = receive(in);
            assertEquals("ok", ok.asArrayValue().get(0).asStringValue().asString());
            assertEquals(2 * 3 * 16 * 4, ok.asArrayValue().get(1).asMapValue().map()
                    .get(org.msgpack.value.ValueFactory.newString("sonar")).asBinaryValue().asByteArray().length);

            send(out, "step", new byte[7], null);
            assertTrue(receive(in).toJson().startsWith("[\"error\",\"value\",\"actions of 7 bytes; this batch takes 48"));
            byte[] nan = new byte[48];
            java.nio.ByteBuffer.wrap(nan).order(java.nio.ByteOrder.LITTLE_ENDIAN).putFloat(4 * 4 + 4, Float.NaN);
            send(out, "step", nan, null);
            assertEquals("[\"error\",\"value\",\"world 0, robot c: action field 1 is NaN\"]", receive(in).toJson());
            send(out, "jump");
            assertEquals("[\"error\",\"bad_call\",\"no call \\\"jump\\\" (step, reset, measure, bye)\"]",
                    receive(in).toJson());
            send(out, "measure", org.msgpack.value.ValueFactory.newArray(org.msgpack.value.ValueFactory.newInteger(0)));
            assertEquals("[\"error\",\"bad_call\",\"this host measures no episode metric (--episode-metric)\"]",
                    receive(in).toJson());
            send(out, "reset", org.msgpack.value.ValueFactory.newArray(org.msgpack.value.ValueFactory.newNil()));
            assertEquals("[\"error\",\"value\",\"1 seeds for 2 worlds\"]", receive(in).toJson());
            send(out, "reset", org.msgpack.value.ValueFactory.newArray(org.msgpack.value.ValueFactory.newNil(),
                    org.msgpack.value.ValueFactory.newInteger(3)));
            Value reset = receive(in);
            byte[] steps = reset.asArrayValue().get(1).asMapValue().map().get(org.msgpack.value.ValueFactory
                    .newString("steps")).asBinaryValue().asByteArray();
            java.nio.LongBuffer each = java.nio.ByteBuffer.wrap(steps).order(java.nio.ByteOrder.LITTLE_ENDIAN).asLongBuffer();
            assertEquals(2, each.get(0), "world 0 (nil) stays: its settling step and the one step");
            assertEquals(1, each.get(1), "world 1 begins again");
            MessageBufferPacker trailing = MessagePack.newDefaultBufferPacker();
            trailing.packArrayHeader(1).packString("bye").packInt(0);
            LinkFrames.write(out, trailing.toByteArray());
            assertEquals("[\"error\",\"bad_call\",\"a request frame holds more than its array\"]", receive(in).toJson());

            send(out, "bye");
            assertEquals("[\"ok\"]", receive(in).toJson());
            assertEquals(2L, served.get(WAIT_S, TimeUnit.SECONDS), "a step and a reset");
        }
    }

    @Test
    void aHelloWithoutTheKeyOrOfAnotherLinkIsRefusedAndAnsweredWhy() throws Exception {
        for (String[] c : new String[][] {{"wrong", "a hello with another key than this link was started with"},
                {"robot", "not a learning link's hello (link \"robosim-robot-link\", not \"robosim-batch-link\")"},
                {"more", "a hello frame holds more than its map"},
                {"version", "version is not a whole number"}}) {
            Future<Long> served = serve("k1");
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort())) {
                DataOutputStream out = new DataOutputStream(s.getOutputStream());
                MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
                switch (c[0]) {
                    case "robot" -> p.packMapHeader(2).packString("link").packString("robosim-robot-link")
                            .packString("version").packInt(1);
                    case "more" -> p.packMapHeader(3).packString("link").packString(BatchLink.NAME).packString("version")
                            .packInt(1).packString("key").packString("k1").packInt(0); // (the learning link's hello,
                            // checked as strictly as the robot link's: LinkHello)
                    case "version" -> p.packMapHeader(3).packString("link").packString(BatchLink.NAME)
                            .packString("version").packString("1").packString("key").packString("k1");
                    default -> {
                        hello(out, c[0]);
                        p = null;
                    }
                }
                if (p != null) {
                    LinkFrames.write(out, p.toByteArray());
                }
                assertEquals("{\"error\":\"" + c[1].replace("\"", "\\\"") + "\"}",
                        receive(new DataInputStream(s.getInputStream())).toJson());
                Exception e = assertThrows(java.util.concurrent.ExecutionException.class,
                        () -> served.get(WAIT_S, TimeUnit.SECONDS));
                assertTrue(e.getCause() instanceof ProtocolException, e.toString());
                assertEquals(c[1], e.getCause().getMessage());
            }
        }
    }
}
