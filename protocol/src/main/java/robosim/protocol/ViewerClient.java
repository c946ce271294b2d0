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
    /** The Environment's first answer: its {@link WorldSnapshot}, or a {@link SimulationEnd} (refused, or over). */
    private final Externalizable first;
    private final CountDownLatch done = new CountDownLatch(1);
    private volatile SimulationEnd end;
    private volatile IOException failure;

    private ViewerClient(ObjectConnection connection, Externalizable first) {
        this.connection = connection;
        this.first = first;
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

    /**
     * As above, proving {@code secret} if the Environment asks for one (null: this process has none). Returns
     * once the Environment has answered (its snapshot, or an end: see {@link #refusal}); a port that answers
     * nothing, or not as an Environment's viewer port, is an IOException naming it and what answered there
     * within the timeout (at least {@link HandshakeDeadline#MIN_MS}).
     */
    public static ViewerClient connect(String host, int port, ViewerHello hello, long timeoutMs, SimulationKeys secret)
            throws IOException, InterruptedException {
        Socket s = Connector.connect(host, port, timeoutMs);
        if (s == null) {
            throw new IOException("cannot connect to the viewer port " + host + ":" + port);
        }
        try {
            ObjectConnection c = ObjectConnection.client(s, ObjectConnection.DEFAULT_RESET_EVERY, secret, timeoutMs);
            c.write(hello);
            c.flush();
            Externalizable first = c.answerChallenge(secret, "viewer");
            if (!(first instanceof WorldSnapshot) && !(first instanceof SimulationEnd)) {
                throw new ProtocolException("expected a WorldSnapshot, got a " + first.getClass().getSimpleName());
            }
            return new ViewerClient(c, first);
        } catch (ProtocolException e) {
            s.close();
            throw new ProtocolException(host + ":" + port + ": " + e.getMessage());
        } catch (IOException e) {
            s.close();
            throw new IOException(host + ":" + port + ": " + e.getMessage(), e);
        } catch (RuntimeException e) {
            s.close();
            throw e;
        }
    }

    /**
     * The Environment's end if it answered this viewer with one instead of its snapshot (a refusal: a port of
     * another kind, a robot to watch that is not there, the wrong keys; or the run was over), else null.
     */
    public SimulationEnd refusal() {
        return first instanceof SimulationEnd e ? e : null;
    }

    /** Starts the reading thread. */
    public void start(Listener listener) {
        Thread t = new Thread(() -> read(listener), "viewer-client");
        t.setDaemon(true);
        t.start();
    }

    private void read(Listener listener) {
        try (connection) {
            if (first instanceof SimulationEnd e) {
                end = e;
                listener.end(e);
                return;
            }
            listener.snapshot((WorldSnapshot) first);
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
