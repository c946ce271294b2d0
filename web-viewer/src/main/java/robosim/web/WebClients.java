package robosim.web;

import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import io.netty.util.concurrent.EventExecutor;
import java.util.HashMap;
import java.util.Map;
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
                offer(page, update);
            }
            if (state != null) {
                send(page, state);
            }
        }
    }

    /** Feed thread: a new world (a simulation, or the same one after a reconnection). */
    void snapshot(String json) {
        io.execute(() -> {
            snapshot = json;
            update = null;
            state = null;
            pages.keySet().forEach(p -> {
                pages.put(p, null); // (an update of the world before is no use)
                send(p, json);
            });
        });
    }

    /** Feed thread: a step. */
    void update(String json) {
        io.execute(() -> {
            update = json;
            pages.keySet().forEach(p -> offer(p, json));
        });
    }

    /** Feed thread: a run state or the end: every page gets it, after the update held for it. */
    void state(String json) {
        io.execute(() -> {
            state = json;
            pages.keySet().forEach(p -> {
                String held = pages.put(p, null);
                if (held != null) {
                    send(p, held);
                }
                send(p, json);
            });
        });
    }

    /** I/O thread: the page can take more; it gets the update held for it, if any. */
    void writable(Channel page) {
        String held = pages.containsKey(page) ? pages.put(page, null) : null;
        if (held != null) {
            offer(page, held);
        }
    }

    private void offer(Channel page, String json) {
        if (page.isWritable()) {
            pages.put(page, null);
            send(page, json);
        } else {
            pages.put(page, json); // (the newest replaces the one held)
        }
    }

    private static void send(Channel page, String json) {
        page.writeAndFlush(new TextWebSocketFrame(json)).addListener(ChannelFutureListener.CLOSE_ON_FAILURE);
    }
}
