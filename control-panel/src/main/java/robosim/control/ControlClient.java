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

/**
 * A client of the Environment's control port: one request line out, one JSON reply line back.
 * Not thread-safe; the window uses it from one background thread.
 */
public final class ControlClient implements Closeable {
    private static final ObjectMapper JSON = new ObjectMapper();
    private final Socket socket;
    private final BufferedReader in;
    private final Writer out;

    /** Connects (and gives the token first, if there is one). */
    public ControlClient(String host, int port, String token, int timeoutMs) throws IOException {
        socket = new Socket();
        socket.connect(new InetSocketAddress(host, port), timeoutMs);
        socket.setSoTimeout(timeoutMs);
        in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        out = new OutputStreamWriter(socket.getOutputStream(), StandardCharsets.UTF_8);
        if (token != null && !token.isEmpty()) {
            JsonNode r = request("token " + token);
            if (!r.path("ok").asBoolean()) {
                close();
                throw new IOException("the Environment refused the token: " + r.path("error").asText());
            }
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
        socket.close();
    }
}
