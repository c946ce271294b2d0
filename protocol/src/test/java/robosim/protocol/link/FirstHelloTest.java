package robosim.protocol.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;

/** A host's first peer among strangers: silent ones, one sending garbage, one with another key, then the peer. */
class FirstHelloTest {
    private static final LinkHello.Link LINK = new LinkHello.Link("test-link", "test link", 1, "peer", List.of("who"));

    private static byte[] hello(String key, String who) throws Exception {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packMapHeader(4).packString("link").packString("test-link").packString("version").packInt(1)
                .packString("key").packString(key).packString("who").packString(who);
        return p.toByteArray();
    }

    private static String answer(Socket s) throws Exception {
        return MessagePack.newDefaultUnpacker(LinkFrames.read(new DataInputStream(s.getInputStream()))).unpackValue()
                .toJson();
    }

    @Test
    void thePeerIsWelcomedWhileStrangersWaitOrAreRefused() throws Exception {
        List<String> refusals = new CopyOnWriteArrayList<>();
        List<Socket> opened = new ArrayList<>();
        try (ServerSocket server = new ServerSocket(0, 16, InetAddress.getLoopbackAddress())) {
            int port = server.getLocalPort();
            for (int i = 0; i < 3; i++) { // (silent: they connect and say nothing)
                opened.add(new Socket(InetAddress.getLoopbackAddress(), port));
            }
            Socket garbage = new Socket(InetAddress.getLoopbackAddress(), port);
            opened.add(garbage);
            garbage.getOutputStream().write("GET / HTTP/1.1\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
            Socket wrong = new Socket(InetAddress.getLoopbackAddress(), port);
            opened.add(wrong);
            LinkFrames.write(new DataOutputStream(wrong.getOutputStream()), hello("k2", "wrong"));
            Socket peer = new Socket(InetAddress.getLoopbackAddress(), port);
            opened.add(peer);
            LinkFrames.write(new DataOutputStream(peer.getOutputStream()), hello("k1", "peer"));

            FirstHello.Welcomed<String> first = FirstHello.await(server, 60_000, 16, socket -> {
                LinkHello h = LinkHello.read(LINK, socket, new DataInputStream(new BufferedInputStream(
                        socket.getInputStream())), new DataOutputStream(socket.getOutputStream()), "k1");
                return h.text("who");
            }, refusals::add);
            assertEquals("peer", first.link());
            first.socket().close();
            assertEquals("{\"error\":\"a hello with another key than this link was started with\"}", answer(wrong));
            assertTrue(answer(garbage).startsWith("{\"error\":\"not a test link's hello frame: a frame of "));
        } finally {
            for (Socket s : opened) {
                s.close();
            }
        }
        // each refusal is said on its hello's thread after its answer (and the silent strangers', closed above, may
        // be said too): the two refused hellos' are waited for, generously
        String garbage = "a hello from 127.0.0.1 refused: not a test link's hello frame: a frame of ";
        String other = "a hello from 127.0.0.1 refused: a hello with another key than this link was started with";
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (!(refusals.stream().anyMatch(r -> r.startsWith(garbage)) && refusals.contains(other))
                && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        assertTrue(refusals.stream().anyMatch(r -> r.startsWith(garbage)) && refusals.contains(other),
                refusals.toString());
        assertTrue(refusals.stream().allMatch(r -> r.startsWith("a hello from 127.0.0.1 refused: ")), refusals.toString());
    }
}
