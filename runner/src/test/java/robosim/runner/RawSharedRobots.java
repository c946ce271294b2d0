package robosim.runner;

import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.List;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotProperties;
import robosim.protocol.SharedHello;
import robosim.protocol.SharedReplies;
import robosim.protocol.SharedRequests;

/**
 * A shared connection by hand (bare object streams), for tests of what the Environment does with its
 * frames: it can send any frame, and cut one short ({@link #sendTruncated}).
 */
final class RawSharedRobots implements AutoCloseable {
    private final Socket socket;
    /** Where the object stream's bytes wait until {@link #release} sends them (all, or some). */
    private final ByteArrayOutputStream held = new ByteArrayOutputStream();
    private final ObjectOutputStream out;
    private final OutputStream wire;
    private final ObjectInputStream in;
    /** The answer to the hellos: a welcome (accepted or refused) for each robot, by slot. */
    final SharedReplies welcomes;

    RawSharedRobots(int port, List<String> names, RobotProperties properties) throws IOException,
            ClassNotFoundException {
        socket = new Socket(InetAddress.getLoopbackAddress(), port);
        try {
            socket.setTcpNoDelay(true);
            wire = new BufferedOutputStream(socket.getOutputStream());
            out = new ObjectOutputStream(held);
            out.writeObject(new SharedHello(names.size()));
            release(Integer.MAX_VALUE);
            in = new ObjectInputStream(socket.getInputStream());
            SharedReplies goOn = (SharedReplies) in.readObject();
            if (goOn.count() != 0) {
                throw new IOException("refused before the hellos, " + goOn.count() + " refusals: "
                        + goOn.welcome(0).reason());
            }
            for (String name : names) {
                out.writeObject(new RobotHello(name, properties));
            }
            release(Integer.MAX_VALUE);
            welcomes = (SharedReplies) in.readObject();
        } catch (IOException | ClassNotFoundException | RuntimeException e) {
            socket.close();
            throw e;
        }
    }

    /** The next frame from the Environment. */
    SharedReplies next() throws IOException, ClassNotFoundException {
        return (SharedReplies) in.readObject();
    }

    /** Sends a frame of requests. */
    void send(SharedRequests frame) throws IOException {
        out.writeObject(frame);
        release(Integer.MAX_VALUE);
    }

    /** Sends the first half of {@code frame}'s bytes, then closes the connection. */
    void sendTruncated(SharedRequests frame) throws IOException {
        out.writeObject(frame);
        out.flush();
        release(held.size() / 2);
        socket.close();
    }

    /** Sends at most {@code bytes} of what the object stream has written. */
    private void release(int bytes) throws IOException {
        out.flush();
        byte[] all = held.toByteArray();
        wire.write(all, 0, Math.min(bytes, all.length));
        wire.flush();
        held.reset();
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
