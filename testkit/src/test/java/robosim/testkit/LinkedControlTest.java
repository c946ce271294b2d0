package robosim.testkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.channels.ServerSocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import robosim.hardware.link.LinkedControl;

/**
 * A robot of a real simulation driven by a controller in another "process" over the robot link (a client thread of
 * this test speaking the link's frames): its move is the robot's move, cut into steps by the Hardware Simulator.
 */
class LinkedControlTest {
    private static byte[] frame(Object... values) throws IOException {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packArrayHeader(values.length);
        for (Object v : values) {
            if (v instanceof String s) {
                p.packString(s);
            } else {
                p.packLong(((Number) v).longValue());
            }
        }
        return p.toByteArray();
    }

    private static String exchange(DataOutputStream out, DataInputStream in, byte[] frame) throws IOException {
        out.writeInt(frame.length);
        out.write(frame);
        out.flush();
        byte[] answer = new byte[in.readInt()];
        in.readFully(answer);
        return MessagePack.newDefaultUnpacker(answer).unpackValue().toJson();
    }

    @Test
    void aControllerOverTheLinkMovesItsRobotAsJavaControlCodeWould() throws Exception {
        ServerSocketChannel listening = ServerSocketChannel.open();
        listening.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 1);
        int port = ((InetSocketAddress) listening.getLocalAddress()).getPort();
        CompletableFuture<List<String>> said = new CompletableFuture<>();
        Thread controller = new Thread(() -> {
            List<String> answers = new ArrayList<>();
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
                DataOutputStream out = new DataOutputStream(s.getOutputStream());
                DataInputStream in = new DataInputStream(s.getInputStream());
                MessageBufferPacker hello = MessagePack.newDefaultBufferPacker();
                hello.packMapHeader(3).packString("link").packString("robosim-robot-link").packString("version")
                        .packInt(1).packString("robot").packString("a");
                answers.add(exchange(out, in, hello.toByteArray()));
                answers.add(exchange(out, in, frame("move", 500)));
                answers.add(exchange(out, in, frame("pose")));
                answers.add(exchange(out, in, frame("bye")));
            } catch (IOException e) {
                answers.add(e.toString());
            }
            said.complete(answers);
        }, "controller");
        controller.setDaemon(true);
        controller.start();
        try (Simulation sim = Simulation.of(World.arena(4, 4).robot("a", "Scout", 1, 2, 0))
                .control("a", new LinkedControl(listening)).start()) {
            sim.run(20); // (a Scout drives 50 mm a step: the move takes 10 steps)
            List<String> answers = said.get(60, TimeUnit.SECONDS);
            assertTrue(answers.get(0).startsWith("{\"link\":\"robosim-robot-link\",\"version\":1,\"robot\":\"a\","
                    + "\"step_ms\":100,\"robots\":[\"a\"],\"seed\":"), answers.toString());
            assertEquals(List.of("[\"ok\",500.0]", "[\"ok\",[1500.0,2000.0,0.0]]", "[\"ok\",null]"),
                    answers.subList(1, answers.size()));
            assertEquals(new Pose(1500, 2000, 0), sim.pose("a"));
            assertEquals(null, sim.failure("a"), "a controller that said bye is control code that returned");
        }
    }

    @Test
    void theEndOfTheSimulationDuringACallIsItsOverReply() throws Exception {
        ServerSocketChannel listening = ServerSocketChannel.open();
        listening.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 1);
        int port = ((InetSocketAddress) listening.getLocalAddress()).getPort();
        Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
        DataOutputStream out = new DataOutputStream(s.getOutputStream());
        DataInputStream in = new DataInputStream(s.getInputStream());
        MessageBufferPacker hello = MessagePack.newDefaultBufferPacker();
        hello.packMapHeader(3).packString("link").packString("robosim-robot-link").packString("version").packInt(1)
                .packString("robot").packString("a");
        byte[] h = hello.toByteArray();
        out.writeInt(h.length);
        out.write(h);
        byte[] sleep = frame("sleep", 1_000_000);
        out.writeInt(sleep.length);
        out.write(sleep);
        out.flush();
        try (s) {
            try (Simulation sim = Simulation.of(World.arena(4, 4).robot("a", "Scout", 1, 2, 0))
                    .control("a", new LinkedControl(listening)).start()) {
                sim.run(5); // (the robot's first call is the sleep: five steps of it are over, it goes on)
            } // (the end: the sleep is interrupted)
            in.readFully(new byte[in.readInt()]); // (the welcome)
            byte[] answer = new byte[in.readInt()];
            in.readFully(answer);
            assertEquals("[\"error\",\"over\",\"the simulation is over\"]",
                    MessagePack.newDefaultUnpacker(answer).unpackValue().toJson());
        }
    }
}
