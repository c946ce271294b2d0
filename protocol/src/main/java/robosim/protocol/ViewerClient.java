package robosim.protocol;

import java.io.Closeable;
import java.io.EOFException;
import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * A headless viewer: connects to an Environment's viewer port, receives the snapshot, then pose
 * updates (and run states: running, paused) until the simulation ends, handing each to a {@link Listener} on its own thread
 * ({@code viewer-client}). Used by the headless runner (pose log, progress) and by tests.
 */
public final class ViewerClient implements Closeable {
    /** Receives what the Environment sends, on the viewer-client thread, in order. */
    public interface Listener {
        void snapshot(WorldSnapshot snapshot);

        void update(PoseUpdate update);

        /** The watched robot's view of the step of the update just before (a viewer that watches one). */
        default void robotView(RobotView view) {
        }

        /** The run started, was paused or resumed (and, first, what it is doing at connect time). */
        default void runState(RunState state) {
        }

        default void end(SimulationEnd end) {
        }

        /** The connection broke before the end. */
        default void lost(IOException cause) {
        }
    }

    private final ObjectConnection connection;
    private final SimulationKeys secret;
    private final CountDownLatch done = new CountDownLatch(1);
    private volatile SimulationEnd end;
    private volatile IOException failure;

    private ViewerClient(ObjectConnection connection, SimulationKeys secret) {
        this.connection = connection;
        this.secret = secret;
    }

    /**
     * Connects and says hello.
     *
     * @param everyStep true for a recording viewer that must see every step
     */
    public static ViewerClient connect(String host, int port, boolean everyStep, long timeoutMs)
            throws IOException, InterruptedException {
        return connect(host, port, new ViewerHello(everyStep), timeoutMs);
    }

    /** Connects and sends the given hello (for a live viewer with an update-rate cap). */
    public static ViewerClient connect(String host, int port, ViewerHello hello, long timeoutMs)
            throws IOException, InterruptedException {
        return connect(host, port, hello, timeoutMs, SimulationKeys.fromEnvironment());
    }

    /** As above, proving {@code secret} if the Environment asks for one (null: this process has none). */
    public static ViewerClient connect(String host, int port, ViewerHello hello, long timeoutMs, SimulationKeys secret)
            throws IOException, InterruptedException {
        Socket s = Connector.connect(host, port, timeoutMs);
        if (s == null) {
            throw new IOException("cannot connect to the viewer port " + host + ":" + port);
        }
        try {
            ObjectConnection c = ObjectConnection.client(s, ObjectConnection.DEFAULT_RESET_EVERY, secret);
            c.write(hello);
            c.flush();
            return new ViewerClient(c, secret);
        } catch (IOException | RuntimeException e) {
            s.close();
            throw e;
        }
    }

    /** Starts the reading thread. */
    public void start(Listener listener) {
        Thread t = new Thread(() -> read(listener), "viewer-client");
        t.setDaemon(true);
        t.start();
    }

    private void read(Listener listener) {
        try (connection) {
            Externalizable first = SimulationKeys.answerChallenge(connection, secret, "viewer");
            if (first instanceof SimulationEnd e) {
                end = e;
                listener.end(e);
                return;
            }
            if (!(first instanceof WorldSnapshot snapshot)) {
                throw new ProtocolException("expected a WorldSnapshot, got a " + first.getClass().getSimpleName());
            }
            listener.snapshot(snapshot);
            while (true) {
                Externalizable m = connection.read(Externalizable.class);
                if (m instanceof PoseUpdate u) {
                    listener.update(u);
                } else if (m instanceof RobotView v) {
                    listener.robotView(v);
                } else if (m instanceof RunState s) {
                    listener.runState(s);
                } else if (m instanceof WorldSnapshot grown) { // robots joined: the updates after it are of this world
                    listener.snapshot(grown);
                } else if (m instanceof SimulationEnd e) {
                    end = e;
                    listener.end(e);
                    return;
                } else {
                    throw new ProtocolException("expected a PoseUpdate, got a " + m.getClass().getSimpleName());
                }
            }
        } catch (EOFException e) {
            failure = new EOFException("the Environment closed the viewer connection before the end");
            listener.lost(failure);
        } catch (IOException e) {
            failure = e;
            listener.lost(e);
        } finally {
            done.countDown();
        }
    }

    /** Waits, for as long as it takes, for the end of the simulation; returns it, or throws what broke the connection. */
    public SimulationEnd awaitEnd() throws IOException, InterruptedException {
        done.await();
        if (failure != null) {
            throw failure;
        }
        return end;
    }

    /** Waits for the end of the simulation; returns it, or throws what broke the connection. */
    public SimulationEnd awaitEnd(long timeout, TimeUnit unit) throws IOException, InterruptedException {
        if (!done.await(timeout, unit)) {
            throw new IOException("no end of simulation within " + timeout + " " + unit);
        }
        if (failure != null) {
            throw failure;
        }
        return end;
    }

    @Override
    public void close() {
        connection.close();
    }
}
