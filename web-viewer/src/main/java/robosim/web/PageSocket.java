package robosim.web;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolHandler;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One page's WebSocket: once open, it joins the {@link WebClients}; each text frame is a request line
 * ({@link #ALLOWED}; anything else is refused, and stop, load or shutdown are not a page's to ask), run
 * on the {@code web-status} thread (status), here ({@code watch ROBOT}: the robot panel's feed) or on the
 * {@code web-commands} thread (the rest, which may wait),
 * and answered with a {@code reply} object. A page has one request in hand at a time, and nothing more is
 * read from it while it has one or does not take what is written to it.
 */
final class PageSocket extends SimpleChannelInboundHandler<TextWebSocketFrame> {
    private static final Logger LOG = LoggerFactory.getLogger(PageSocket.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    static final Set<String> ALLOWED = Set.of("status", "pause", "resume", "step", "seek", "speed", "watch");

    private final WebClients clients;
    private final WebCommands commands;
    private final ExecutorService commandThread;
    private final ExecutorService statusThread;
    /** A request of this page is being answered (I/O thread only): nothing more is read from it till then. */
    private boolean inHand;
    /** Requests read before reading stopped, waiting their turn (I/O thread only). */
    private final java.util.ArrayDeque<String> pending = new java.util.ArrayDeque<>();
    static final int MAX_PENDING = 8;

    PageSocket(WebClients clients, WebCommands commands, ExecutorService commandThread, ExecutorService statusThread) {
        this.clients = clients;
        this.commands = commands;
        this.commandThread = commandThread;
        this.statusThread = statusThread;
    }

    @Override
    public void userEventTriggered(ChannelHandlerContext ctx, Object event) throws Exception {
        if (event instanceof WebSocketServerProtocolHandler.HandshakeComplete) {
            ctx.pipeline().remove(io.netty.handler.timeout.ReadTimeoutHandler.class); // (a page watching sends nothing)
            clients.joined(ctx.channel());
        }
        super.userEventTriggered(ctx, event);
    }

    @Override
    public void channelWritabilityChanged(ChannelHandlerContext ctx) throws Exception {
        if (ctx.channel().isWritable()) {
            clients.writable(ctx.channel());
        }
        readWhileItReads(ctx);
        super.channelWritabilityChanged(ctx);
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, TextWebSocketFrame frame) {
        if (pending.size() >= MAX_PENDING) { // (frames already read when reading stopped: a few at most)
            LOG.warn("web viewer: a page sent more than {} requests ahead of its replies; closing", MAX_PENDING);
            ctx.close();
            return;
        }
        String line = frame.text().strip();
        if (!(line.equals("status") && pending.contains(line))) { // (one status waiting is as good as many)
            pending.add(line);
        }
        next(ctx);
    }

    /** Starts this page's next request, unless one is in hand (one at a time: the next once its reply has left). */
    private void next(ChannelHandlerContext ctx) {
        if (inHand || pending.isEmpty()) {
            readWhileItReads(ctx);
            return;
        }
        String[] w = pending.poll().split("\\s+", 2);
        String verb = w[0].toLowerCase(Locale.ROOT);
        String arg = w.length > 1 ? w[1].strip() : "";
        inHand = true;
        readWhileItReads(ctx);
        if (!ALLOWED.contains(verb)) {
            reply(ctx, verb, WebJson.refusal("a page may ask " + String.join(", ", ALLOWED.stream().sorted().toList())));
            return;
        }
        if (verb.equals("watch")) { // (the page's own business: answered here, on the I/O thread)
            reply(ctx, verb, clients.watch(ctx.channel(), arg));
            return;
        }
        ExecutorService runner = verb.equals("status") ? statusThread : commandThread;
        try {
            runner.execute(() -> {
                String answer = WebJson.refusal("failed");
                try {
                    answer = commands.handle(verb, arg);
                } catch (Exception e) {
                    answer = WebJson.refusal(String.valueOf(e.getMessage()));
                } finally { // (whatever happens, the page gets a reply and is read again)
                    String a = answer;
                    ctx.executor().execute(() -> reply(ctx, verb, a));
                }
            });
        } catch (RejectedExecutionException e) {
            reply(ctx, verb, WebJson.refusal("busy; try again"));
        }
    }

    /** Reads from this page only while it has no request in hand and takes what is written to it. */
    private void readWhileItReads(ChannelHandlerContext ctx) {
        ctx.channel().config().setAutoRead(!inHand && ctx.channel().isWritable());
    }

    /** I/O thread: the reply to this page's request; its next request is read once it has left. */
    private void reply(ChannelHandlerContext ctx, String verb, String answer) {
        ObjectNode n;
        try {
            n = (ObjectNode) JSON.readTree(answer == null ? WebJson.refusal("unknown request") : answer);
        } catch (Exception e) {
            LOG.warn("web viewer: a reply that is not JSON: {}", e.toString());
            n = (ObjectNode) JSON.createObjectNode().put("ok", false).put("error", "no answer");
        }
        n.put("type", "reply");
        n.put("request", verb);
        ctx.channel().writeAndFlush(new TextWebSocketFrame(n.toString())).addListener(f -> {
            inHand = false;
            if (f.isSuccess()) {
                next(ctx);
            } else {
                ctx.close();
            }
        });
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        LOG.debug("web viewer: a page's connection failed: {}", cause.toString());
        ctx.close();
    }
}
