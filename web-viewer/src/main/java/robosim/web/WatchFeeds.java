package robosim.web;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import robosim.protocol.SimulationKeys;

/**
 * The feeds that watch one robot each for the pages ({@link WebFeed} with a robot's name): opened when a
 * page first watches that robot, closed when the last one stops, all closed with the server. Opening
 * starts the feed's own thread ({@code web-watch-N}) and never blocks; any thread.
 */
final class WatchFeeds {
    private final String host;
    private final int viewerPort;
    private final SimulationKeys keys;
    private final Set<WebFeed> open = ConcurrentHashMap.newKeySet();
    private final AtomicInteger serial = new AtomicInteger();
    private volatile boolean closed;

    WatchFeeds(String host, int viewerPort, SimulationKeys keys) {
        this.host = host;
        this.viewerPort = viewerPort;
        this.keys = keys;
    }

    /** A new feed watching {@code robot}, started, sending to {@code clients} (once the server is closing: never started). */
    WebFeed open(String robot, WebClients clients) {
        WebFeed f = new WebFeed(host, viewerPort, keys, robot, "web-watch-" + serial.incrementAndGet());
        open.add(f);
        if (closed) { // (a page's request handled as the server closes)
            close(f);
            return f;
        }
        f.start(clients);
        if (closed) { // (closeAll ran meanwhile, perhaps before this one was in the set)
            close(f);
        }
        return f;
    }

    void close(WebFeed f) {
        open.remove(f);
        f.close();
    }

    void closeAll() {
        closed = true;
        for (WebFeed f : open) {
            close(f);
        }
    }
}
