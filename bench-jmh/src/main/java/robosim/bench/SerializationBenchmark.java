package robosim.bench;

import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Serializable against Externalizable for the same per-step messages: a StepRequest and a
 * StepResponse (8 sonar ranges), each written to and read back from an object stream that, like
 * {@code ObjectConnection}, is long-lived and reset every 256 messages. One operation = one message
 * written and read, each a fresh object as every step's is. Bytes per message: {@link MessageSizes}.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class SerializationBenchmark {
    @Param({"externalizable", "serializable"})
    public String form;

    @Param({"request", "response"})
    public String message;

    private final Pipe pipe = new Pipe();
    private boolean externalizable;
    private long k;

    @Setup(Level.Trial)
    public void setUp() throws IOException {
        externalizable = form.equals("externalizable");
        pipe.open();
    }

    /** A fresh message with fresh nested values, as every step's is. */
    static Object make(String message, boolean externalizable) {
        double[] sonar = {1000, 1200, 1400, 1600, 1800, 2000, 2200, 2400};
        if (message.equals("request")) {
            return externalizable ? new StepRequest(7, 250, 0, true, List.of(), List.of())
                    : new SerializableStepRequest(7, 250, List.of());
        }
        return externalizable ? new StepResponse(7, 250, 0, "", 1000, 2000, 0, sonar, List.of(), List.of())
                : new SerializableStepResponse(7, sonar);
    }

    @Benchmark
    public Object writeAndRead() throws IOException, ClassNotFoundException {
        return pipe.roundTrip(make(message, externalizable), ++k % 256 == 0);
    }

    /** A long-lived object stream writing into a buffer that the reading stream drains. */
    static final class Pipe {
        private final ResettableBuffer buffer = new ResettableBuffer();
        private ObjectOutputStream out;
        private ObjectInputStream in;

        void open() throws IOException {
            out = new ObjectOutputStream(buffer);
            out.flush();
            in = new ObjectInputStream(buffer.input());
        }

        Object roundTrip(Object value, boolean reset) throws IOException, ClassNotFoundException {
            out.writeUnshared(value);
            if (reset) {
                out.reset();
            }
            out.flush();
            return in.readUnshared();
        }
    }

    /** A byte buffer written at one end and read at the other, reusing its array. */
    static final class ResettableBuffer extends java.io.OutputStream {
        private byte[] data = new byte[1 << 16];
        private int writePos;
        private int readPos;

        @Override
        public void write(int b) {
            ensure(1);
            data[writePos++] = (byte) b;
        }

        @Override
        public void write(byte[] b, int off, int len) {
            ensure(len);
            System.arraycopy(b, off, data, writePos, len);
            writePos += len;
        }

        private void ensure(int n) {
            if (readPos == writePos) {
                readPos = 0;
                writePos = 0;
            }
            if (writePos + n > data.length) {
                data = java.util.Arrays.copyOf(data, Math.max(data.length * 2, writePos + n));
            }
        }

        java.io.InputStream input() {
            return new java.io.InputStream() {
                @Override
                public int read() {
                    return readPos < writePos ? data[readPos++] & 0xFF : -1;
                }

                @Override
                public int read(byte[] b, int off, int len) {
                    if (readPos >= writePos) {
                        return -1;
                    }
                    int n = Math.min(len, writePos - readPos);
                    System.arraycopy(data, readPos, b, off, n);
                    readPos += n;
                    return n;
                }

                @Override
                public int available() {
                    return writePos - readPos;
                }
            };
        }
    }

}
