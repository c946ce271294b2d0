package robosim.control;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.Closeable;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import robosim.protocol.LineProof;
import robosim.protocol.SimulationKeys;

/**
 * A client of the Environment's control port: one request line out, one JSON reply line back.
 * Not thread-safe; the window uses it from one background thread.
 */
public final class ControlClient implements Closeable {
    private static final ObjectMapper JSON = new ObjectMapper();
    /** The TCP socket, under {@link #socket} when it is TLS. */
    private final Socket transport;
    private final Socket socket;
    private final BufferedReader in;
    private final Writer out;

    /**
     * Connects; with {@code keys}, over TLS when they hold the simulation's key pair, and proves the
     * shared secret before anything else (null: neither).
     */
    public ControlClient(String host, int port, SimulationKeys keys, int timeoutMs) throws IOException {
        transport = new Socket();
        try {
            transport.connect(new InetSocketAddress(host, port), timeoutMs);
            transport.setSoTimeout(timeoutMs);
            socket = keys == null || keys.tls() == null ? transport : keys.tls().client(transport);
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
            out = new OutputStreamWriter(socket.getOutputStream(), StandardCharsets.UTF_8);
            if (keys != null) {
                prove(keys);
            }
        } catch (IOException | RuntimeException e) {
            transport.close();
            throw e;
        }
    }

    private void prove(SimulationKeys keys) throws IOException {
        JsonNode challenge = request(LineProof.CHALLENGE);
        String nonce = challenge.path("nonce").asText();
        if (!challenge.path("ok").asBoolean() || nonce.isEmpty()) {
            throw new IOException("the Environment gave no challenge: " + challenge.path("error").asText());
        }
        JsonNode r = request(LineProof.answer(keys, LineProof.CONTROL, nonce));
        if (!r.path("ok").asBoolean()) {
            throw new IOException("the Environment refused the proof of the shared secret: " + r.path("error").asText());
        }
    }

    /** Sends one request and returns the reply ({@code ok}, and {@code message} or {@code error}, ...). */
    public JsonNode request(String line) throws IOException {
        if (line.indexOf('\n') >= 0 || line.indexOf('\r') >= 0) {
            throw new IllegalArgumentException("a request is one line");
        }
        out.write(line + "\n");
        out.flush();
        String reply = in.readLine();
        if (reply == null) {
            throw new IOException("the Environment closed the control connection");
        }
        return JSON.readTree(reply);
    }

    /** Sets how long a request may wait for its reply (a long "step N" may need more). */
    public void setTimeoutMs(int ms) throws IOException {
        socket.setSoTimeout(ms);
    }

    @Override
    public void close() throws IOException {
        transport.close();
        socket.close();
    }
}
