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

/**
 * The pages connected to the feed. Every page gets the world it joins (the last snapshot, the newest
 * update, the last run state), then every run state and end, in order, and updates: the newest one
 * whenever its connection can take it, so a page that reads slowly skips steps instead of piling them up
 * (netty's write buffer watermarks say when it can); an update held for a page goes out before the next
 * state or end. Everything here happens on netty's one I/O thread ({@code web-io}, which serves every
 * page): the feed's thread only hands it over, and never blocks.
 */
final class WebClients {
    private final EventExecutor io;
    private final Consumer<WebClients> firstPage;
    /** Each page, with the update held for it (null: none): the I/O thread's own, as everything below. */
    private final Map<Channel, String> pages = new HashMap<>();
    private String snapshot;
    private String update;
    private String state;

    /**
     * @param io the I/O thread every page's channel is on
     * @param firstPage runs when a page joins (it starts the feed, once: a replay starts with its first viewer)
     */
    WebClients(EventExecutor io, Consumer<WebClients> firstPage) {
        this.io = io;
        this.firstPage = firstPage;
    }

    /** I/O thread: a page has opened its WebSocket: it gets what the feed has so far. */
    void joined(Channel page) {
        pages.put(page, null);
        firstPage.accept(this);
        page.closeFuture().addListener(f -> pages.remove(page));
        if (snapshot != null) {
            send(page, snapshot);
            if (update != null) {
                send(page, update);
            }
            if (state != null) {
                send(page, state);
            }
        }
    }

    /** Feed thread: a new world (a simulation, or the same one after a reconnection). */
    void snapshot(String json) {
        onIo(() -> {
            snapshot = json;
            update = null;
            state = null;
            for (Channel p : List.copyOf(pages.keySet())) { // (a failed write closes and removes a page)
                pages.replace(p, null); // (an update of the world before is no use)
                send(p, json);
            }
        });
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

    /** I/O thread: the page can take more; it gets the update held for it, if any. */
    void writable(Channel page) {
        String held = pages.replace(page, null);
        if (held != null) {
            offer(page, held);
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
