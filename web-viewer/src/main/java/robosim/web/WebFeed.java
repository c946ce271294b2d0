package robosim.web;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.PoseUpdate;
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
 * ({@link WebClients}). Its thread {@code web-feed} connects when the first page joins, and again after each simulation's
 * end (an Environment that runs one simulation after another), once a second while there is none.
 */
final class WebFeed implements ViewerClient.Listener {
    private static final Logger LOG = LoggerFactory.getLogger(WebFeed.class);
    /** Updates a second the feed asks for: what a page draws, at most. */
    static final int UPDATES_PER_SECOND = 30;

    private final String host;
    private final int viewerPort;
    private final SimulationKeys keys;
    private final CountDownLatch closed = new CountDownLatch(1);
    private final Thread thread;
    private final java.util.concurrent.atomic.AtomicBoolean started = new java.util.concurrent.atomic.AtomicBoolean();
    private volatile ViewerClient viewer;
    private volatile WebClients clients;

    WebFeed(String host, int viewerPort, SimulationKeys keys) {
        this.host = host;
        this.viewerPort = viewerPort;
        this.keys = keys;
        this.thread = new Thread(this::follow, "web-feed");
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
        try {
            while (closed.getCount() > 0) {
                try {
                    ViewerClient v = ViewerClient.connect(host, viewerPort, new ViewerHello(false, UPDATES_PER_SECOND),
                            5_000, keys);
                    viewer = v;
                    told = false;
                    v.start(this);
                    v.awaitEnd();
                } catch (IOException e) {
                    if (!told) {
                        LOG.info("web viewer: no simulation on {}:{} ({}); trying again every second", host, viewerPort,
                                e.getMessage());
                        told = true;
                    }
                }
                closed.await(1, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void snapshot(WorldSnapshot snapshot) {
        clients.snapshot(WebJson.snapshot(snapshot));
    }

    @Override
    public void update(PoseUpdate update) {
        clients.update(WebJson.update(update));
    }

    @Override
    public void runState(RunState state) {
        clients.state(WebJson.state(state));
    }

    @Override
    public void end(SimulationEnd end) {
        clients.state(WebJson.end(end));
    }

    void close() {
        closed.countDown();
        ViewerClient v = viewer;
        if (v != null) {
            v.close();
        }
    }
}
