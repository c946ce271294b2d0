package robosim.protocol;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.Externalizable;
import java.io.IOException;
import java.io.InputStream;
import java.io.ObjectInput;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketAddress;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;

/**
 * Coverage-guided fuzzing of message decoding (Jazzer), two ways chosen by the first input byte's low
 * bit. Through the stream: any bytes after a valid stream header, read through {@link ObjectConnection}
 * exactly as every RoboSim process reads its peer, must end in a message or an {@link IOException} (a
 * {@link ProtocolException} for anything malformed); the second byte chooses which reads to interleave
 * (step numbers and objects), as the robot, viewer and geometry links do. Raw: the rest of the first
 * byte chooses a message class, whose own {@code readExternal} reads the bytes from a plain
 * {@link ObjectInput} with no stream framing in front of it (which reaches every count and bound check
 * of every message), and must end the same way. Any other exception, an OutOfMemoryError or a hang is
 * a finding.
 *
 * <p>In every build it replays the regression inputs; {@code JAZZER_FUZZ=1} fuzzes (the build does so
 * for {@code fuzz.seconds}, scripts/fuzz.sh for as long as it is told: the annotation's duration is only
 * the default, overridden by the libFuzzer argument the pom passes).
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

    /** Every message class, for the raw mode. */
    private static final List<Supplier<Externalizable>> MESSAGES = List.of(StepRequest::new, StepResponse::new,
            RobotHello::new, RobotWelcome::new, GeometryHello::new, GeometryWorld::new, GeometryStepRequest::new,
            GeometryStepResponse::new, ViewerHello::new, WorldSnapshot::new, PoseUpdate::new, RunState::new,
            SimulationEnd::new, Challenge::new, Proof::new, RobotView::new);

    @FuzzTest(maxDuration = "10s")
    void decodingEndsInAMessageOrAProtocolError(byte[] input) throws Exception {
        if (input.length < 2) {
            return;
        }
        if ((input[0] & 1) == 1) {
            Externalizable message = MESSAGES.get(((input[0] & 0xff) >>> 1) % MESSAGES.size()).get();
            try {
                message.readExternal(new RawObjectInput(Arrays.copyOfRange(input, 1, input.length)));
            } catch (IOException expected) {
                // malformed or out of bounds: the connection would be dropped with this reason
            }
            return;
        }
        int pattern = input[1] & 0xff;
        byte[] stream = new byte[HEADER.length + input.length - 2];
        System.arraycopy(HEADER, 0, stream, 0, HEADER.length);
        System.arraycopy(input, 2, stream, HEADER.length, input.length - 2);
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

    /** Fixed bytes as a plain {@link ObjectInput}: primitives only (messages hold no nested objects). */
    private static final class RawObjectInput extends DataInputStream implements ObjectInput {
        RawObjectInput(byte[] bytes) {
            super(new ByteArrayInputStream(bytes));
        }

        @Override
        public Object readObject() throws IOException {
            throw new ProtocolException("a message asked for a nested object");
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
