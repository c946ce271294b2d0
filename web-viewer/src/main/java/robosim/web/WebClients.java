package robosim.web;

import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import io.netty.util.concurrent.EventExecutor;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Consumer;
import robosim.protocol.RobotView;

/**
 * The pages connected to the feed. Every page gets the world it joins (the last snapshot, the newest
 * update, the last run state), then every run state and end, in order, and updates: the newest one
 * whenever its connection can take it, so a page that reads slowly skips steps instead of piling them up
 * (netty's write buffer watermarks say when it can); an update held for a page goes out before the next
 * state or end. A page may watch one robot ({@link #watch}): it then also gets that robot's views from a
 * feed watching it ({@link WatchFeeds}: one per robot, however many pages watch it, at most
 * {@link #MAX_WATCHED} robots at once), the newest whenever it can take it, with the messages of the
 * views it could not take merged in. Everything here happens on netty's one I/O thread ({@code web-io},
 * which serves every page): the feeds' threads only hand things over, and never block.
 */
final class WebClients {
    private final EventExecutor io;
    private final Consumer<WebClients> firstPage;
    /** Each page, with the update held for it (null: none): the I/O thread's own, as everything below. */
    private final Map<Channel, String> pages = new HashMap<>();
    private String snapshot;
    private String update;
    private String state;
    /** What the world's loop functions have drawn (whole), for the pages that join, and as their message. */
    private robosim.protocol.Traces drawing = robosim.protocol.Traces.NONE;
    private String drawingJson;
    /** What each page that could not take more missed of the drawing, joined: sent when it can. */
    private final Map<Channel, robosim.protocol.Traces> heldDrawing = new HashMap<>();
    static final int MAX_WATCHED = 8;
    private final WatchFeeds watchFeeds;
    private List<String> robots = List.of();
    /** The robot each page watches, the feed of each robot watched, the view held for each page. */
    private final Map<Channel, String> watching = new HashMap<>();
    private final Map<String, WebFeed> feedOf = new HashMap<>();
    private final Map<Channel, RobotView> heldView = new HashMap<>();

    /**
     * @param io the I/O thread every page's channel is on
     * @param firstPage runs when a page joins (it starts the feed, once: a replay starts with its first viewer)
     */
    WebClients(EventExecutor io, Consumer<WebClients> firstPage, WatchFeeds watchFeeds) {
        this.io = io;
        this.firstPage = firstPage;
        this.watchFeeds = watchFeeds;
    }

    /** I/O thread: a page has opened its WebSocket: it gets what the feed has so far. */
    void joined(Channel page) {
        pages.put(page, null);
        firstPage.accept(this);
        page.closeFuture().addListener(f -> {
            pages.remove(page);
            heldDrawing.remove(page);
            unwatch(page);
        });
        if (snapshot != null) {
            send(page, snapshot);
            if (drawing.traces() > 0) {
                send(page, drawingJson());
            }
            if (update != null) {
                send(page, update);
            }
            if (state != null) {
                send(page, state);
            }
        }
    }

    /**
     * Feed thread: a new world (a simulation, or the same one after a reconnection) and its robots' names;
     * {@code sameRun}: the run goes on in it (robots joined, or a replay's seek), so its state and the views
     * held for pages stay.
     */
    void snapshot(String json, List<String> names, boolean sameRun) {
        onIo(() -> {
            snapshot = json;
            robots = List.copyOf(names);
            update = null;
            drawing = robosim.protocol.Traces.NONE; // (the feed sends the new world's, if it has one)
            heldDrawing.clear();
            drawingJson = null;
            if (!sameRun) {
                state = null;
                heldView.clear(); // (views of the run before are no use)
            }
            for (Channel p : List.copyOf(pages.keySet())) { // (a failed write closes and removes a page)
                pages.replace(p, null); // (an update of the world before is no use)
                send(p, json);
            }
        });
    }

    /**
     * Feed thread: what the loop functions drew ({@code piece}) goes to every page that can take it, in order, and is
     * joined to what a page that cannot has missed; {@code whole}, the drawing so far, goes to the pages that join.
     */
    void traces(robosim.protocol.Traces piece, robosim.protocol.Traces whole) {
        onIo(() -> {
            drawing = whole;
            drawingJson = null;
            String json = null;
            for (Channel p : List.copyOf(pages.keySet())) {
                robosim.protocol.Traces held = heldDrawing.remove(p);
                if (held == null && p.isWritable()) {
                    json = json == null ? WebJson.traces(piece) : json;
                    send(p, json);
                } else { // (it is behind: what it missed, joined, when it can take more)
                    heldDrawing.put(p, held == null ? piece : held.then(piece));
                }
            }
        });
    }

    /** The whole drawing as a page's message, made once a drawing (a page that joins gets it). */
    private String drawingJson() {
        if (drawingJson == null) {
            drawingJson = WebJson.traces(drawing);
        }
        return drawingJson;
    }

    /** Feed thread: a step. */
    void update(String json) {
        onIo(() -> {
            update = json;
            for (Channel p : List.copyOf(pages.keySet())) {
                offer(p, json);
            }
        });
    }

    /** Feed thread: a run state or the end: every page gets it, after the update held for it. */
    void state(String json) {
        onIo(() -> {
            state = json;
            for (Channel p : List.copyOf(pages.keySet())) {
                String held = pages.replace(p, null);
                if (held != null) {
                    send(p, held);
                }
                send(p, json);
            }
        });
    }

    /**
     * I/O thread: the page can take more; it gets what it missed of the drawing, the update and the view held for it,
     * if any.
     */
    void writable(Channel page) {
        robosim.protocol.Traces missed = page.isWritable() ? heldDrawing.remove(page) : null;
        if (missed != null) {
            send(page, WebJson.traces(missed));
        }
        String held = pages.replace(page, null);
        if (held != null) {
            offer(page, held);
        }
        RobotView v = heldView.remove(page);
        if (v != null) {
            offerView(page, v);
        }
    }

    /**
     * I/O thread: {@code page} watches {@code robot} from now on ("" for none); the reply to its request
     * (refused: a name that is no robot of the run, or more than {@link #MAX_WATCHED} robots watched).
     */
    String watch(Channel page, String robot) {
        if (!robot.isEmpty() && !robots.contains(robot)) {
            return WebJson.refusal("no robot of this run is called " + robot);
        }
        String was = watching.get(page);
        boolean frees = was != null && !was.equals(robot) && watching.values().stream().filter(was::equals).count() == 1;
        if (!robot.isEmpty() && !feedOf.containsKey(robot) && feedOf.size() - (frees ? 1 : 0) >= MAX_WATCHED) {
            return WebJson.refusal("the pages watch " + MAX_WATCHED + " robots already; stop watching one first");
        }
        unwatch(page);
        if (robot.isEmpty()) {
            return WebJson.ok("watching none");
        }
        watching.put(page, robot);
        feedOf.computeIfAbsent(robot, r -> watchFeeds.open(r, this));
        return WebJson.ok("watching " + robot);
    }

    private void unwatch(Channel page) {
        heldView.remove(page);
        String was = watching.remove(page);
        if (was != null && !watching.containsValue(was)) {
            WebFeed f = feedOf.remove(was);
            if (f != null) {
                watchFeeds.close(f);
            }
        }
    }

    /** Watch feed's thread: robot {@code robot}'s view of a step, for the pages watching it. */
    void view(String robot, RobotView v) {
        onIo(() -> {
            for (Map.Entry<Channel, String> w : List.copyOf(watching.entrySet())) {
                if (w.getValue().equals(robot)) {
                    offerView(w.getKey(), v.after(heldView.remove(w.getKey())));
                }
            }
        });
    }

    /** Watch feed's thread: it has joined the run after step {@code step}: the views of every step after follow. */
    void watchStarted(String robot, long step) {
        String json = WebJson.watchStarted(robot, step);
        onIo(() -> {
            for (Map.Entry<Channel, String> w : List.copyOf(watching.entrySet())) {
                if (w.getValue().equals(robot)) {
                    send(w.getKey(), json);
                }
            }
        });
    }

    /** Watch feed's thread: the Environment refused to let it watch {@code robot} (not in this run). */
    void watchRefused(String robot, String reason) {
        onIo(() -> {
            for (Map.Entry<Channel, String> w : List.copyOf(watching.entrySet())) {
                if (w.getValue().equals(robot)) {
                    unwatch(w.getKey());
                    send(w.getKey(), WebJson.viewEnded(robot, reason));
                }
            }
        });
    }

    private void offerView(Channel page, RobotView v) {
        if (!watching.containsKey(page)) {
            return;
        }
        if (page.isWritable()) {
            send(page, WebJson.view(watching.get(page), v));
        } else {
            heldView.put(page, v); // (merged with the next, so no message is skipped)
        }
    }

    private void offer(Channel page, String json) {
        if (!pages.containsKey(page)) {
            return; // (it has gone)
        }
        if (page.isWritable()) {
            pages.replace(page, null);
            send(page, json);
        } else {
            pages.replace(page, json); // (the newest replaces the one held)
        }
    }

    /** Hands {@code task} to the I/O thread; nothing, once the server is shutting down. */
    private void onIo(Runnable task) {
        try {
            io.execute(task);
        } catch (RejectedExecutionException e) {
            // (closing: no page is served any more)
        }
    }

    private static void send(Channel page, String json) {
        page.writeAndFlush(new TextWebSocketFrame(json)).addListener(ChannelFutureListener.CLOSE_ON_FAILURE);
    }
}
