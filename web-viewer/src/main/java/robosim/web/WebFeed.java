package robosim.web;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.SimulationKeys;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldSnapshot;

/**
 * What the pages see: one live viewer of the Environment (or replay) it serves, on its viewer port like
 * any other viewer, so it sits behind the same coalescing viewer queue and never slows a step. Each
 * message is turned into the page's JSON ({@link WebJson}) once and handed to every page
 * ({@link WebClients}). Its thread {@code web-feed} connects when the first page joins, and again after each
 * simulation's end (an Environment that runs one simulation after another): a second later after a run it
 * watched, up to 10 s later while there is none. A feed that watches a robot (for the pages that watch it,
 * {@link WatchFeeds}) passes on only that robot's views, on its thread {@code web-watch-N}.
 */
final class WebFeed implements ViewerClient.Listener {
    private static final Logger LOG = LoggerFactory.getLogger(WebFeed.class);
    /**
     * Updates a second the feed asks for: what a page draws, at most. A browser on the machine of the run
     * competes with it: with 30 a page cost the paper benchmark about 0.4 of its speed on 2 cores, with 10
     * a few per cent (web-viewer/README.md).
     */
    static final int UPDATES_PER_SECOND = 10;

    private final String host;
    private final int viewerPort;
    private final SimulationKeys keys;
    /** The robot watched ("" for none: the pages' main feed). */
    private final String watch;
    private final CountDownLatch closed = new CountDownLatch(1);
    /** What the loop functions have drawn, pieced together from the updates (the feed thread's). */
    private final robosim.protocol.Traces.Log drawing = new robosim.protocol.Traces.Log();
    private final Thread thread;
    private final java.util.concurrent.atomic.AtomicBoolean started = new java.util.concurrent.atomic.AtomicBoolean();
    private volatile ViewerClient viewer;
    /** Updates of the current connection (its reading thread counts; the feed thread reads it after the end). */
    private volatile long updates;
    /** Whether the current connection has had its first snapshot (its reading thread's, reset by the feed thread). */
    private volatile boolean worldSeen;
    private volatile WebClients clients;

    WebFeed(String host, int viewerPort, SimulationKeys keys) {
        this(host, viewerPort, keys, "", "web-feed");
    }

    /** A feed that watches robot {@code watch} ("" for none), on a thread named {@code threadName}. */
    WebFeed(String host, int viewerPort, SimulationKeys keys, String watch, String threadName) {
        this.host = host;
        this.viewerPort = viewerPort;
        this.keys = keys;
        this.watch = watch;
        this.thread = new Thread(this::follow, threadName);
        thread.setDaemon(true);
    }

    /** Starts following, once, sending what it sees to {@code pages}. */
    void start(WebClients pages) {
        if (started.compareAndSet(false, true)) {
            clients = pages;
            thread.start();
        }
    }

    private void follow() {
        boolean told = false;
        long waitMs = 500; // (doubled before the first wait)
        try {
            while (closed.getCount() > 0) {
                updates = 0;
                try {
                    ViewerClient v = ViewerClient.connect(host, viewerPort, new ViewerHello(false, UPDATES_PER_SECOND, watch),
                            5_000, keys);
                    viewer = v;
                    if (closed.getCount() == 0) { // (closed while it connected)
                        v.close();
                        return;
                    }
                    told = false;
                    worldSeen = false;
                    v.start(this);
                    v.awaitEnd();
                } catch (IOException e) {
                    if (!told) {
                        LOG.info("web viewer: no simulation on {}:{} ({}); trying again", host, viewerPort, e.getMessage());
                        told = true;
                    }
                }
                // an Environment between simulations answers with an end at once: ask less often then
                waitMs = updates > 0 ? 1000 : Math.min(10_000, waitMs * 2);
                closed.await(waitMs, TimeUnit.MILLISECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void snapshot(WorldSnapshot snapshot) {
        boolean sameRun = worldSeen; // (a later snapshot of a connection: robots joined, or a replay's seek)
        worldSeen = true;
        if (watch.isEmpty()) {
            clients.snapshot(WebJson.snapshot(snapshot), snapshot.robotNames(), sameRun);
            drawing.erase();
            drawn(snapshot.poses()); // (a snapshot's drawing is whole: the pages begin it afresh)
        } else if (!sameRun) { // (a later world is of the same watch: joined robots, a seek; no new start)
            clients.watchStarted(watch, snapshot.step()); // (its views follow from the next step on)
        }
    }

    @Override
    public void update(PoseUpdate update) {
        updates++;
        if (watch.isEmpty()) {
            drawn(update);
            clients.update(WebJson.update(update));
        }
    }

    /**
     * What the loop functions drew in {@code u} goes to every page as it comes (not held back as an update may be:
     * a page pieces the drawing together), the whole drawing kept for the pages that join.
     */
    private void drawn(PoseUpdate u) {
        robosim.protocol.Traces piece = u.traces();
        if (u.lightsOn() == null || piece.isEmpty()) {
            return;
        }
        try {
            drawing.apply(piece);
        } catch (robosim.protocol.ProtocolException e) { // (only a fault sends a piece that does not follow)
            LOG.warn("web viewer: a drawing's piece refused: {}", e.getMessage());
            drawing.erase();
            piece = drawing.whole();
        }
        clients.traces(piece, drawing.whole());
    }

    @Override
    public void robotView(RobotView view) {
        clients.view(watch, view);
    }

    @Override
    public void runState(RunState state) {
        if (watch.isEmpty()) {
            clients.state(WebJson.state(state));
        }
    }

    @Override
    public void end(SimulationEnd end) {
        if (watch.isEmpty()) {
            clients.state(WebJson.end(end));
        } else if (end.lastStep() == -1 && updates == 0 && end.reason().startsWith("it would watch")) {
            clients.watchRefused(watch, end.reason()); // (no robot of that name in this run)
        }
    }

    @Override
    public void lost(IOException cause) {
        if (closed.getCount() == 0 || !watch.isEmpty()) {
            return; // (closing: nobody to tell; a watch: the main feed tells the pages)
        }
        clients.state(WebJson.end(new SimulationEnd(-1, "the viewer connection was lost: " + cause.getMessage())));
    }

    void close() {
        closed.countDown();
        ViewerClient v = viewer;
        if (v != null) {
            v.close();
        }
    }
}
