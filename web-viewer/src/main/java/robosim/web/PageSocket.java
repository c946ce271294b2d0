package robosim.web;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.netty.channel.ChannelFutureListener;
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
 * on the {@code web-commands} thread and answered with a {@code reply} object.
 */
final class PageSocket extends SimpleChannelInboundHandler<TextWebSocketFrame> {
    private static final Logger LOG = LoggerFactory.getLogger(PageSocket.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    static final Set<String> ALLOWED = Set.of("status", "pause", "resume", "step", "seek", "speed");

    private final WebClients clients;
    private final WebCommands commands;
    private final ExecutorService commandThread;

    PageSocket(WebClients clients, WebCommands commands, ExecutorService commandThread) {
        this.clients = clients;
        this.commands = commands;
        this.commandThread = commandThread;
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
        super.channelWritabilityChanged(ctx);
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, TextWebSocketFrame frame) {
        String line = frame.text().strip();
        String[] w = line.split("\\s+", 2);
        String verb = w[0].toLowerCase(Locale.ROOT);
        String arg = w.length > 1 ? w[1].strip() : "";
        if (!ALLOWED.contains(verb)) {
            reply(ctx, verb, "{\"ok\":false,\"error\":\"a page may ask " + String.join(", ", ALLOWED.stream().sorted().toList())
                    + "\"}");
            return;
        }
        try {
            commandThread.execute(() -> {
                String answer;
                try {
                    answer = commands.handle(verb, arg);
                } catch (Exception e) {
                    answer = error(String.valueOf(e.getMessage()));
                }
                reply(ctx, verb, answer);
            });
        } catch (RejectedExecutionException e) {
            reply(ctx, verb, error("busy; try again"));
        }
    }

    private static String error(String message) {
        ObjectNode n = JSON.createObjectNode();
        n.put("ok", false);
        n.put("error", message);
        return n.toString();
    }

    private static void reply(ChannelHandlerContext ctx, String verb, String answer) {
        try {
            ObjectNode n = (ObjectNode) JSON.readTree(answer == null ? error("unknown request") : answer);
            n.put("type", "reply");
            n.put("request", verb);
            ctx.channel().writeAndFlush(new TextWebSocketFrame(n.toString()))
                    .addListener(ChannelFutureListener.CLOSE_ON_FAILURE);
        } catch (Exception e) {
            LOG.warn("web viewer: a reply that is not JSON: {}", e.toString());
        }
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        LOG.debug("web viewer: a page's connection failed: {}", cause.toString());
        ctx.close();
    }
}
