package robosim.viewer;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * Keeps a viewer on an Environment across runs, on its own thread ({@code viewer-follow}): it
 * watches one connection until the simulation ends or the connection is lost, then keeps the last
 * picture, says "waiting for the next run on HOST:PORT" and tries to connect again - first after
 * {@code firstRetryMs}, then at doubling intervals up to {@code maxRetryMs} - until the next
 * simulation (Stop then Start, or Load, on the control port) listens on the viewer port, and shows
 * that one from its snapshot. With {@code giveUpMs} > 0 it stops trying after that long without a
 * run and says so; 0 tries for as long as the window is open. A connection that ends before it
 * hears what its run is doing (an Environment that was closing) counts as a failed attempt, so the
 * intervals keep growing.
 */
public final class RunFollower {
    /** Receives every connection's messages, in order, and what the viewer does between runs. */
    public interface Listener extends ViewerClient.Listener {
        /** Between runs (on the viewer-follow thread): e.g. "waiting for the next run on localhost:3000". */
        void between(String doing);
    }

    private final String host;
    private final int port;
    private final ViewerHello hello;
    private final Listener feed;
    private final long firstRetryMs;
    private final long maxRetryMs;
    private final long giveUpMs;
    private final CountDownLatch closed = new CountDownLatch(1);
    private volatile ViewerClient current;
    private volatile boolean heardState;

    public RunFollower(String host, int port, ViewerHello hello, Listener feed, long firstRetryMs, long maxRetryMs,
            long giveUpMs) {
        if (firstRetryMs < 1 || maxRetryMs < firstRetryMs || giveUpMs < 0) {
            throw new IllegalArgumentException("need 1 <= firstRetryMs <= maxRetryMs and giveUpMs >= 0, got "
                    + firstRetryMs + ", " + maxRetryMs + ", " + giveUpMs);
        }
        this.host = host;
        this.port = port;
        this.hello = hello;
        this.feed = feed;
        this.firstRetryMs = firstRetryMs;
        this.maxRetryMs = maxRetryMs;
        this.giveUpMs = giveUpMs;
    }

    /** Starts following from a connection already made (its hello sent, not yet started). */
    public void start(ViewerClient first) {
        Thread t = new Thread(() -> follow(first), "viewer-follow");
        t.setDaemon(true);
        t.start();
    }

    /** Stops following and closes the connection in use. Any thread. */
    public void close() {
        closed.countDown();
        ViewerClient c = current;
        if (c != null) {
            c.close();
        }
    }

    private void follow(ViewerClient first) {
        ViewerClient client = first;
        long retryMs = firstRetryMs;
        try {
            while (client != null) {
                heardState = false;
                current = client;
                client.start(new Watch());
                try {
                    client.awaitEnd();
                } catch (IOException lost) {
                    // the feed has been told why
                }
                retryMs = heardState ? firstRetryMs : Math.min(maxRetryMs, retryMs * 2);
                String where = host + ":" + port;
                feed.between("waiting for the next run on " + where);
                long since = System.nanoTime();
                client = null;
                while (client == null) {
                    if (closed.await(retryMs, TimeUnit.MILLISECONDS)) {
                        return;
                    }
                    if (giveUpMs > 0 && System.nanoTime() - since >= TimeUnit.MILLISECONDS.toNanos(giveUpMs)) {
                        feed.between("no next run on " + where + " within " + giveUpMs / 1000 + " s; gave up");
                        return;
                    }
                    try {
                        client = ViewerClient.connect(host, port, hello, 0);
                    } catch (IOException notYet) {
                        retryMs = Math.min(maxRetryMs, retryMs * 2);
                    }
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Passes everything on to the feed and notes that this connection heard what its run is doing. */
    private final class Watch implements ViewerClient.Listener {
        @Override
        public void snapshot(WorldSnapshot snapshot) {
            feed.snapshot(snapshot);
        }

        @Override
        public void update(PoseUpdate update) {
            feed.update(update);
        }

        @Override
        public void robotView(RobotView view) {
            feed.robotView(view);
        }

        @Override
        public void runState(RunState state) {
            heardState = true;
            feed.runState(state);
        }

        @Override
        public void end(SimulationEnd end) {
            feed.end(end);
        }

        @Override
        public void lost(IOException cause) {
            feed.lost(cause);
        }
    }
}
