package robosim.web;

import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.handler.codec.http.DefaultFullHttpResponse;
import io.netty.handler.codec.http.FullHttpRequest;
import io.netty.handler.codec.http.FullHttpResponse;
import io.netty.handler.codec.http.HttpHeaderNames;
import io.netty.handler.codec.http.HttpMethod;
import io.netty.handler.codec.http.HttpResponseStatus;
import io.netty.handler.codec.http.HttpUtil;
import io.netty.handler.codec.http.HttpVersion;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Set;

/**
 * Every HTTP request first: only GET, a WebSocket only from this server's own page (its Origin), and only
 * the {@link StaticFiles}; over plain HTTP (loopback) only with a Host that names this machine (a page of
 * another site that a DNS name re-pointed at 127.0.0.1 gets nothing; over TLS such a page fails the
 * handshake, whose certificate names no site and which asks for the simulation's key pair). Everything
 * else is answered with its status and closed.
 */
final class HttpGate extends SimpleChannelInboundHandler<FullHttpRequest> {
    private static final Set<String> LOCAL_HOSTS = Set.of("localhost", "127.0.0.1", "[::1]");

    private final StaticFiles files;
    /** Behind TLS with the simulation's key pair: any Host (beyond loopback), pages on https. */
    private final boolean tls;

    HttpGate(StaticFiles files, boolean tls) {
        super(false); // (a WebSocket request goes on to the next handler, which releases it)
        this.files = files;
        this.tls = tls;
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, FullHttpRequest request) {
        try {
            String host = request.headers().get(HttpHeaderNames.HOST, "");
            if (!request.decoderResult().isSuccess() || !request.method().equals(HttpMethod.GET)) {
                refuse(ctx, HttpResponseStatus.BAD_REQUEST, "GET only");
            } else if (!tls && !LOCAL_HOSTS.contains(hostName(host))) {
                refuse(ctx, HttpResponseStatus.MISDIRECTED_REQUEST, "this viewer answers only as localhost");
            } else if (request.uri().equals("/ws")) {
                String origin = request.headers().get(HttpHeaderNames.ORIGIN);
                if (origin != null && !origin.equalsIgnoreCase((tls ? "https://" : "http://") + host)) {
                    refuse(ctx, HttpResponseStatus.FORBIDDEN, "a WebSocket only from this viewer's own page");
                } else {
                    ctx.fireChannelRead(request.retain());
                }
            } else {
                StaticFiles.File f = files.get(request.uri());
                if (f == null) {
                    refuse(ctx, HttpResponseStatus.NOT_FOUND, "not found");
                } else {
                    FullHttpResponse r = new DefaultFullHttpResponse(HttpVersion.HTTP_1_1, HttpResponseStatus.OK,
                            Unpooled.wrappedBuffer(f.bytes()));
                    r.headers().set(HttpHeaderNames.CONTENT_TYPE, f.contentType())
                            .set("X-Content-Type-Options", "nosniff")
                            .set("Content-Security-Policy", "default-src 'self'; connect-src 'self'; "
                                    + "img-src 'self' data:; style-src 'self' 'unsafe-inline'; frame-ancestors 'none'")
                            .set(HttpHeaderNames.CACHE_CONTROL, "no-cache");
                    HttpUtil.setContentLength(r, f.bytes().length);
                    boolean keepAlive = HttpUtil.isKeepAlive(request);
                    HttpUtil.setKeepAlive(r, keepAlive);
                    ctx.writeAndFlush(r).addListener(keepAlive ? ChannelFutureListener.CLOSE_ON_FAILURE
                            : ChannelFutureListener.CLOSE);
                }
            }
        } finally {
            request.release();
        }
    }

    /** The host name of a Host header ({@code name:port}, {@code [v6]:port}), lower case. */
    static String hostName(String host) {
        String h = host.toLowerCase(Locale.ROOT);
        int colon = h.lastIndexOf(':');
        if (colon > 0 && h.indexOf(']') < colon) {
            h = h.substring(0, colon);
        }
        return h;
    }

    private static void refuse(ChannelHandlerContext ctx, HttpResponseStatus status, String why) {
        FullHttpResponse r = new DefaultFullHttpResponse(HttpVersion.HTTP_1_1, status,
                Unpooled.copiedBuffer(why + "\n", StandardCharsets.UTF_8));
        r.headers().set(HttpHeaderNames.CONTENT_TYPE, "text/plain; charset=utf-8");
        HttpUtil.setContentLength(r, r.content().readableBytes());
        ctx.writeAndFlush(r).addListener(ChannelFutureListener.CLOSE);
    }
}
