package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.io.Serializable;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The connection wrapper over a real loopback socket pair on an ephemeral port. */
class ObjectConnectionTest {
    /** The peers' side, a thread each (they block in socket reads: never the common pool). */
    private static final java.util.concurrent.Executor PEERS = r -> {
        Thread t = new Thread(r, "test-peer");
        t.setDaemon(true);
        t.start();
    };

    private ServerSocket server;
    private Socket clientSocket;
    private Socket serverSocket;

    @BeforeEach
    void connect() throws Exception {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        clientSocket = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort());
        serverSocket = server.accept();
    }

    @AfterEach
    void close() throws IOException {
        clientSocket.close();
        serverSocket.close();
        server.close();
    }

    private ObjectConnection[] pair(int resetEvery) throws Exception {
        CompletableFuture<ObjectConnection> a = CompletableFuture.supplyAsync(() -> open(clientSocket, resetEvery), PEERS);
        ObjectConnection b = new ObjectConnection(serverSocket, resetEvery);
        return new ObjectConnection[] {a.get(10, TimeUnit.SECONDS), b};
    }

    private static ObjectConnection open(Socket s, int resetEvery) {
        try {
            return new ObjectConnection(s, resetEvery);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void stepsAndMessagesArriveInOrderAcrossManyResets() throws Exception {
        ObjectConnection[] c = pair(3);
        for (int k = 0; k < 1000; k++) {
            c[0].writeStep(k);
            c[0].write(new StepRequest(k, k, 0, false, List.of()));
        }
        c[0].flush();
        for (int k = 0; k < 1000; k++) {
            assertEquals(k, c[1].readStep());
            assertEquals(k, c[1].read(StepRequest.class).moveMm());
        }
        assertTrue(clientSocket.getTcpNoDelay());
    }

    @Test
    void theReferenceBoundIsPerMessageNotPerStreamLife() throws Exception {
        // with a bound of 100 objects per message, 5,000 one-object messages must all pass: the JDK's
        // count only ever grows, so a bound on it would end every connection after 100 messages
        CompletableFuture<ObjectConnection> a = CompletableFuture.supplyAsync(() -> open(clientSocket, 64), PEERS);
        ObjectConnection b = new ObjectConnection(serverSocket, 64, new ProtocolFilter(100));
        ObjectConnection c = a.get(10, TimeUnit.SECONDS);
        CompletableFuture<Void> writer = CompletableFuture.runAsync(() -> {
            try {
                for (int k = 0; k < 5000; k++) {
                    c.write(new StepRequest(k, 0, 0, false, List.of()));
                }
                c.flush();
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        }, PEERS);
        for (int k = 0; k < 5000; k++) {
            assertEquals(k, b.read(StepRequest.class).step());
        }
        writer.get(10, TimeUnit.SECONDS);
    }

    @Test
    void resetIsWrittenEveryNMessages() throws Exception {
        int messages = 10;
        int descriptor = descriptorBytes();
        long never = sentBytes(0, messages);
        for (int every : new int[] {1, 3, 10}) {
            int resets = messages / every;
            int resentDescriptors = (messages - 1) / every;
            assertEquals(never + resets + (long) resentDescriptors * descriptor, sentBytes(every, messages),
                    "reset every " + every);
        }
    }

    /** Bytes the class descriptor of GeometryHello takes: first copy minus a repeated copy. */
    private static int descriptorBytes() throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ObjectOutputStream out = new ObjectOutputStream(bytes);
        out.flush();
        int header = bytes.size();
        out.writeUnshared(new GeometryHello());
        out.flush();
        int first = bytes.size() - header;
        return first - MessageRoundTripTest.repeatedSize(new GeometryHello());
    }

    /** Bytes the connection puts on the wire for n messages, read off the raw socket. */
    private long sentBytes(int resetEvery, int messages) throws Exception {
        try (ServerSocket ss = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
                Socket client = new Socket(InetAddress.getLoopbackAddress(), ss.getLocalPort());
                Socket raw = ss.accept()) {
            CompletableFuture<byte[]> bytes = CompletableFuture.supplyAsync(() -> {
                try {
                    new ObjectOutputStream(raw.getOutputStream()).flush();
                    return raw.getInputStream().readAllBytes();
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }, PEERS);
            ObjectConnection c = new ObjectConnection(client, resetEvery);
            for (int i = 0; i < messages; i++) {
                c.write(new GeometryHello());
            }
            c.flush();
            c.close();
            return bytes.get(10, TimeUnit.SECONDS).length;
        }
    }

    @Test
    void aClassOutsideTheAllowListIsRefusedByName() throws Exception {
        ObjectOutputStream raw = rawPeer();
        ObjectConnection c = new ObjectConnection(serverSocket, 0);
        raw.writeObject(new Gadget());
        raw.flush();
        ProtocolException e = assertThrows(ProtocolException.class, () -> c.read(StepRequest.class));
        assertTrue(e.getMessage().contains(Gadget.class.getName()), e.getMessage());
    }

    @Test
    void aProxyClassIsRefusedBeforeAnyClassIsLoadedForIt() throws Exception {
        ObjectOutputStream raw = rawPeer();
        ObjectConnection c = new ObjectConnection(serverSocket, 0);
        java.lang.reflect.InvocationHandler handler = (java.lang.reflect.InvocationHandler & Serializable) (p, m, a) -> null;
        raw.writeObject(java.lang.reflect.Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {Runnable.class}, handler));
        raw.flush();
        ProtocolException e = assertThrows(ProtocolException.class, () -> c.read(StepRequest.class));
        assertEquals("refused: a proxy class is not a protocol message", e.getMessage());
    }

    @Test
    void aHugeArrayIsRefusedBeforeItIsAllocated() throws Exception {
        ObjectOutputStream raw = rawPeer();
        ObjectConnection c = new ObjectConnection(serverSocket, 0);
        raw.writeObject(new double[(int) ProtocolFilter.MAX_ARRAY_LENGTH + 1]);
        raw.flush();
        ProtocolException e = assertThrows(ProtocolException.class, () -> c.read(StepRequest.class));
        assertTrue(e.getMessage().contains("array length"), e.getMessage());
    }

    @Test
    void aDeepObjectGraphIsRefused() throws Exception {
        ObjectOutputStream raw = rawPeer();
        ObjectConnection c = new ObjectConnection(serverSocket, 0);
        List<Object> nested = new ArrayList<>();
        List<Object> inner = nested;
        for (int i = 0; i < 10; i++) {
            List<Object> next = new ArrayList<>();
            inner.add(next);
            inner = next;
        }
        raw.writeObject(nested);
        raw.flush();
        assertThrows(ProtocolException.class, () -> c.read(StepRequest.class));
    }

    @Test
    void aMessageOfAnotherClassIsRefusedBeforeAnyOfItIsRead() throws Exception {
        ObjectConnection[] c = pair(0);
        c[1].limitMessageBytes(Limits.MAX_HELLO_BYTES); // (a stranger)
        GeometryStepResponse big = new GeometryStepResponse(1, 4000); // (its fields would take 32 KB)
        for (int i = 0; i < 4000; i++) {
            big.addRange(i);
        }
        c[0].write(big);
        c[0].flush();
        ProtocolException e = assertThrows(ProtocolException.class, () -> c[1].read(RobotHello.class));
        assertEquals("expected a RobotHello, got a GeometryStepResponse", e.getMessage(),
                "refused at its class, before its counts could allocate or its bytes run past the stranger's cap");
    }

    @Test
    void aWrongMessageTypeIsNamed() throws Exception {
        ObjectConnection[] c = pair(0);
        c[0].write(new GeometryHello());
        c[0].flush();
        ProtocolException e = assertThrows(ProtocolException.class, () -> c[1].read(RobotHello.class));
        assertEquals("expected a RobotHello, got a GeometryHello", e.getMessage());
    }

    @Test
    void garbageInsteadOfAnObjectStreamIsRefused() throws Exception {
        OutputStream out = clientSocket.getOutputStream();
        out.write("GET / HTTP/1.0\r\n\r\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        out.flush();
        ProtocolException e = assertThrows(ProtocolException.class, () -> new ObjectConnection(serverSocket, 0));
        assertEquals("it sent \"GET / HTTP/1.0\" (HTTP), not RoboSim's object protocol", e.getMessage());
    }

    @Test
    void aMessageLargerThanTheBudgetIsRefused() throws Exception {
        ByteArrayOutputStream probe = new ByteArrayOutputStream();
        new ObjectOutputStream(probe).close();
        MessageBudgetInputStream in = new MessageBudgetInputStream(
                new java.io.ByteArrayInputStream(new byte[100]), 10);
        in.startMessage();
        assertThrows(ProtocolException.class, () -> in.readNBytes(11));
        in.startMessage();
        assertEquals(5, in.readNBytes(5).length);
    }

    private ObjectOutputStream rawPeer() throws IOException {
        ObjectOutputStream raw = new ObjectOutputStream(clientSocket.getOutputStream());
        raw.flush();
        return raw;
    }

    /** Stands in for a deserialization gadget: any Serializable class that is not a protocol message. */
    static final class Gadget implements Serializable {
        private static final long serialVersionUID = 1L;
    }
}
