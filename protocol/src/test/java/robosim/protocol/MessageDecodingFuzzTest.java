package robosim.protocol;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.Externalizable;
import java.io.IOException;
import java.io.InputStream;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketAddress;

/**
 * Coverage-guided fuzzing of message decoding (Jazzer): any bytes after a valid stream header, read
 * through {@link ObjectConnection} exactly as every RoboSim process reads its peer, must end in a
 * message or an {@link IOException} (a {@link ProtocolException} for anything malformed). Any other
 * exception, an OutOfMemoryError or a hang is a finding. The first input byte chooses which reads to
 * interleave (step numbers and objects), as the robot, viewer and geometry links do.
 *
 * <p>In every build it replays the regression inputs; {@code JAZZER_FUZZ=1} fuzzes (the build does so
 * for {@code fuzz.duration}, scripts/fuzz.sh for longer).
 */
class MessageDecodingFuzzTest {
    private static final byte[] HEADER = header();

    private static byte[] header() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.flush();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
        return bytes.toByteArray();
    }

    @FuzzTest(maxDuration = "20s")
    void decodingEndsInAMessageOrAProtocolError(byte[] input) throws Exception {
        if (input.length == 0) {
            return;
        }
        int pattern = input[0] & 0xff;
        byte[] stream = new byte[HEADER.length + input.length - 1];
        System.arraycopy(HEADER, 0, stream, 0, HEADER.length);
        System.arraycopy(input, 1, stream, HEADER.length, input.length - 1);
        ObjectConnection c = new ObjectConnection(new BytesSocket(stream), ObjectConnection.DEFAULT_RESET_EVERY);
        try {
            for (int i = 0; i < 8; i++) {
                if ((pattern >> i & 1) == 0) {
                    c.read(Externalizable.class);
                } else {
                    c.readStep();
                }
            }
        } catch (IOException expected) {
            // malformed, refused or truncated: the connection would be dropped with this reason
        }
    }

    /** A socket whose input is fixed bytes and whose output goes nowhere. */
    private static final class BytesSocket extends Socket {
        private final InputStream in;

        BytesSocket(byte[] input) {
            this.in = new ByteArrayInputStream(input);
        }

        @Override
        public InputStream getInputStream() {
            return in;
        }

        @Override
        public OutputStream getOutputStream() {
            return OutputStream.nullOutputStream();
        }

        @Override
        public void setTcpNoDelay(boolean on) {
        }

        @Override
        public SocketAddress getRemoteSocketAddress() {
            return new InetSocketAddress("fuzz.invalid", 1);
        }

        @Override
        public synchronized void close() {
        }
    }
}
