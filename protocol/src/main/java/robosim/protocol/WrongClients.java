package robosim.protocol;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;

/**
 * What a port says to a client that speaks another protocol than its own (see {@link Greeting}), in that
 * client's protocol, so that it can show why it was turned away: an object-protocol client gets a
 * {@link SimulationEnd} (every RoboSim client takes one as a refusal), an HTTP client a {@code 400} whose body
 * says what the port is, a line client (the Control Panel) one line in the control port's form
 * ({@code {"ok":false,"error":"..."}}). The answer is written, the sending side shut, and what the client
 * still sends read and dropped until it closes (at most {@value #DRAINED_BYTES} bytes), so that the answer
 * is not lost to a reset; the caller's deadline bounds the wait.
 */
public final class WrongClients {
    /** The most a turned-away client's further bytes are read before its connection is closed anyway. */
    private static final int DRAINED_BYTES = 64 * 1024;

    private WrongClients() {
    }

    /** An object stream holding {@code end} alone: Java's stream header, then the message. */
    public static byte[] objectRefusal(SimulationEnd end) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(256);
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeUnshared(end);
        } catch (IOException e) {
            throw new UncheckedIOException("writing to memory", e);
        }
        return bytes.toByteArray();
    }

    /** An HTTP response {@code 400} whose body says {@code why}. */
    public static byte[] httpRefusal(String why) {
        byte[] body = (why + "\n").getBytes(StandardCharsets.UTF_8);
        String head = "HTTP/1.1 400 Bad Request\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: "
                + body.length + "\r\nConnection: close\r\n\r\n";
        byte[] all = new byte[head.length() + body.length];
        System.arraycopy(head.getBytes(StandardCharsets.US_ASCII), 0, all, 0, head.length());
        System.arraycopy(body, 0, all, head.length(), body.length);
        return all;
    }

    /** One line of the control port's protocol refusing with {@code why}. */
    public static byte[] lineRefusal(String why) {
        return ("{\"ok\":false,\"error\":\"" + why.replace("\\", "\\\\").replace("\"", "\\\"") + "\"}\n")
                .getBytes(StandardCharsets.UTF_8);
    }

    /** What an object-protocol port says to an HTTP or line client: what it is, and where the Control Panel goes. */
    public static String objectPortIs(String port) {
        return "this is " + port + ", which speaks RoboSim's object protocol (robots, viewers, Geometry); the Control "
                + "Panel uses the control port (" + Protocol.DEFAULT_CONTROL_PORT + " by default), a browser the web "
                + "port (--web-port)";
    }

    /** Turns a client away without a word (its protocol is none this port could answer in), then closes. */
    static void turnAway(Socket raw) throws IOException {
        answer(raw, new byte[0]);
    }

    /** Answers an object-protocol client on {@code raw} with {@code end}, then closes (see the class comment). */
    static void refuse(Socket raw, SimulationEnd end) throws IOException {
        answer(raw, objectRefusal(end));
    }

    /** Answers an HTTP client on {@code raw}, saying what {@code port} is, then closes. */
    static void answerHttp(Socket raw, String port) throws IOException {
        answer(raw, httpRefusal(objectPortIs(port)));
    }

    /** Answers a line client on {@code raw}, saying what {@code port} is, then closes. */
    static void answerLine(Socket raw, String port) throws IOException {
        answer(raw, lineRefusal(objectPortIs(port)));
    }

    /** (Over TLS, {@code raw} is the TLS socket: the answer goes encrypted, and the sending side stays open.) */
    private static void answer(Socket raw, byte[] answer) throws IOException {
        try (raw) {
            OutputStream out = raw.getOutputStream();
            out.write(answer);
            out.flush();
            if (!(raw instanceof javax.net.ssl.SSLSocket)) {
                raw.shutdownOutput();
            }
            InputStream in = raw.getInputStream();
            byte[] sink = new byte[4096];
            int drained = 0;
            for (int n; drained < DRAINED_BYTES && (n = in.read(sink)) >= 0; ) {
                drained += n;
            }
        }
    }
}
