package robosim.web;

import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import io.netty.util.AttributeKey;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The pages connected to the feed. Every page gets the world it joins (the last snapshot, the newest
 * update, the last run state), then every run state and end, and updates: the newest one whenever its
 * connection can take it, so a page that reads slowly skips steps instead of piling them up (netty's
 * write buffer watermarks say when it can). Called by the {@code web-feed}'s reading thread and netty's
 * I/O thread; never blocks either.
 */
final class WebClients {
    private static final AttributeKey<String> HELD = AttributeKey.valueOf("robosim.heldUpdate");

    private final Map<Channel, Boolean> pages = new ConcurrentHashMap<>();
    private final java.util.function.Consumer<WebClients> firstPage;
    private volatile String snapshot;
    private volatile String update;
    private volatile String state;

    /** {@code firstPage} runs when a page joins (it starts the feed, once: a replay starts with its first viewer). */
    WebClients(java.util.function.Consumer<WebClients> firstPage) {
        this.firstPage = firstPage;
    }

    /** A page has opened its WebSocket: it gets what the feed has so far. */
    void joined(Channel page) {
        pages.put(page, Boolean.TRUE);
        firstPage.accept(this);
        page.closeFuture().addListener(f -> pages.remove(page));
        String s = snapshot;
        if (s != null) {
            send(page, s);
            String u = update;
            if (u != null) {
                offer(page, u);
            }
            String st = state;
            if (st != null) {
                send(page, st);
            }
        }
    }

    void snapshot(String json) {
        synchronized (this) { // (a page joining sees a snapshot and the update after it, never older ones)
            snapshot = json;
            update = null;
        }
        pages.keySet().forEach(p -> send(p, json));
    }

    void update(String json) {
        update = json;
        pages.keySet().forEach(p -> offer(p, json));
    }

    /** A run state or the end: every page gets it. */
    void state(String json) {
        state = json;
        pages.keySet().forEach(p -> send(p, json));
    }

    /** Netty's I/O thread: the page can take more; it gets the update held for it, if any. */
    void writable(Channel page) {
        String held = page.attr(HELD).getAndSet(null);
        if (held != null) {
            offer(page, held);
        }
    }

    private static void offer(Channel page, String json) {
        if (page.isWritable()) {
            page.attr(HELD).set(null);
            page.writeAndFlush(new TextWebSocketFrame(json)).addListener(ChannelFutureListener.CLOSE_ON_FAILURE);
        } else {
            page.attr(HELD).set(json); // (the newest replaces the one held)
        }
    }

    private static void send(Channel page, String json) {
        page.writeAndFlush(new TextWebSocketFrame(json)).addListener(ChannelFutureListener.CLOSE_ON_FAILURE);
    }
}
