package robosim.environment.control;

import com.fasterxml.jackson.databind.node.ObjectNode;
import io.netty.bootstrap.ServerBootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.channel.nio.NioEventLoopGroup;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.handler.codec.LineBasedFrameDecoder;
import io.netty.handler.codec.TooLongFrameException;
import io.netty.handler.codec.string.StringDecoder;
import io.netty.handler.codec.string.StringEncoder;
import io.netty.handler.timeout.IdleStateEvent;
import io.netty.handler.timeout.IdleStateHandler;
import java.io.Closeable;
import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The control port (netty): one request per line, one JSON reply per line, always in the order of the
 * connection's requests ({@link ControlRequests} says what each does). Requests that wait (step, pause,
 * start, load) run on one {@code control} thread, the others on {@code control-quick}, never on netty's
 * I/O thread ({@code control-io}); a connection has one request in hand at a time and at most
 * {@link #MAX_PIPELINED} queued behind it. Bounded: {@link #MAX_LINE} bytes a line (a longer one gets an
 * error and the connection is closed), {@link #MAX_CONNECTIONS} connections at once (one more is closed
 * at once), a connection with nothing in hand that sends nothing for {@link #IDLE_MINUTES} minutes is
 * closed. With a token set, every request before a correct {@code token} line is refused.
 */
public final class ControlServer implements Closeable {
    private static final Logger LOG = LoggerFactory.getLogger(ControlServer.class);
    /** The longest request line, bytes. */
    public static final int MAX_LINE = 4096;
    /** Connections the port holds at once. */
    public static final int MAX_CONNECTIONS = 64;
    /** Requests one connection may have queued behind the one in hand; one more closes it. */
    public static final int MAX_PIPELINED = 32;
    /** A connection with nothing in hand is closed after this long without a request, minutes. */
    public static final int IDLE_MINUTES = 5;

    private final ControlRequests requests;
    private final EventLoopGroup group = new NioEventLoopGroup(1,
            (java.util.concurrent.ThreadFactory) r -> named(r, "control-io"));
    /** Requests that wait, one at a time (at most one per connection is ever queued). */
    private final ExecutorService worker = single("control");
    /** Requests that answer at once (status, resume, stop, shutdown), so a long step never holds them up. */
    private final ExecutorService quick = single("control-quick");
    private final AtomicInteger connections = new AtomicInteger();
    private Channel server;

    /**
     * @param token required before any other request, or null for none (loopback only)
     * @param directories where {@code load} may read files
     */
    public ControlServer(EnvironmentHost host, String token, EnvironmentDirectories directories) {
        this.requests = new ControlRequests(host, token == null || token.isEmpty() ? null : token, directories);
    }

    private static Thread named(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    private static ExecutorService single(String name) {
        return new ThreadPoolExecutor(1, 1, 0, TimeUnit.MILLISECONDS, new ArrayBlockingQueue<>(MAX_CONNECTIONS),
                r -> named(r, name));
    }

    /** Binds; a port in use is a {@link BindException} naming it. */
    public void start(InetAddress bind, int port) throws IOException {
        ServerBootstrap b = new ServerBootstrap().group(group).channel(NioServerSocketChannel.class)
                .childHandler(new ChannelInitializer<SocketChannel>() {
                    @Override
                    protected void initChannel(SocketChannel ch) {
                        if (connections.incrementAndGet() > MAX_CONNECTIONS) {
                            connections.decrementAndGet();
                            LOG.warn("control port: {} closed at once: {} connections already", ch.remoteAddress(),
                                    MAX_CONNECTIONS);
                            ch.close();
                            return;
                        }
                        ch.closeFuture().addListener(f -> connections.decrementAndGet());
                        ch.pipeline().addLast(new IdleStateHandler(IDLE_MINUTES, 0, 0, TimeUnit.MINUTES),
                                new LineBasedFrameDecoder(MAX_LINE, true, true),
                                new StringDecoder(StandardCharsets.UTF_8), new StringEncoder(StandardCharsets.UTF_8),
                                new Handler());
                    }
                });
        try {
            server = b.bind(new InetSocketAddress(bind, port)).sync().channel();
        } catch (Exception e) {
            close();
            if (e instanceof BindException) {
                throw new BindException("control port " + port + " is already in use");
            }
            throw new IOException("cannot listen on control port " + port + ": " + e.getMessage(), e);
        }
    }

    public int port() {
        return ((InetSocketAddress) server.localAddress()).getPort();
    }

    @Override
    public void close() {
        if (server != null) {
            server.close();
        }
        group.shutdownGracefully(0, 1, TimeUnit.SECONDS);
        worker.shutdownNow();
        quick.shutdownNow();
    }

    /** One per connection; its fields are touched on the I/O thread only. */
    private final class Handler extends SimpleChannelInboundHandler<String> {
        private final ControlRequests.Caller caller = requests.caller();
        private final ArrayDeque<String> pending = new ArrayDeque<>();
        /** A request of this connection is being handled; its reply goes out before the next starts. */
        private boolean inHand;

        @Override
        protected void channelRead0(ChannelHandlerContext ctx, String line) {
            String request = line.strip();
            if (request.isEmpty()) {
                return;
            }
            if (pending.size() >= MAX_PIPELINED) {
                LOG.warn("control port: {} sent more than {} requests ahead of its replies; closing",
                        ctx.channel().remoteAddress(), MAX_PIPELINED);
                pending.clear();
                ctx.close();
                return;
            }
            pending.add(request);
            ctx.channel().config().setAutoRead(false); // read on once this connection's requests are answered
            next(ctx);
        }

        /** Starts the next request of this connection, if none is in hand. */
        private void next(ChannelHandlerContext ctx) {
            while (!inHand && !pending.isEmpty()) {
                String request = pending.poll();
                String verb = ControlRequests.verb(request);
                if (!caller.authorised && !verb.equals("token")) {
                    reply(ctx, ControlRequests.error("a token is required first: token SECRET"));
                    continue;
                }
                inHand = true;
                try {
                    (ControlRequests.waits(verb) ? worker : quick).execute(() -> {
                        ObjectNode answer = requests.handle(caller, request);
                        ctx.executor().execute(() -> answered(ctx, answer));
                    });
                } catch (RejectedExecutionException e) {
                    inHand = false;
                    reply(ctx, ControlRequests.error("the Environment is shutting down"));
                }
            }
            if (!inHand && pending.isEmpty() && ctx.channel().isActive()) {
                ctx.channel().config().setAutoRead(true);
            }
        }

        private void answered(ChannelHandlerContext ctx, ObjectNode answer) {
            reply(ctx, answer);
            inHand = false;
            next(ctx);
        }

        @Override
        public void userEventTriggered(ChannelHandlerContext ctx, Object event) {
            if (event instanceof IdleStateEvent && !inHand && pending.isEmpty()) {
                LOG.info("control port: {} idle for {} minutes; closing", ctx.channel().remoteAddress(), IDLE_MINUTES);
                ctx.close();
            }
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            if (cause instanceof TooLongFrameException) {
                LOG.warn("control port: {} sent a line over {} bytes; closing", ctx.channel().remoteAddress(), MAX_LINE);
                ctx.writeAndFlush(ControlRequests.error("request longer than " + MAX_LINE + " bytes").toString() + "\n")
                        .addListener(ChannelFutureListener.CLOSE);
            } else {
                LOG.info("control port: {} dropped: {}", ctx.channel().remoteAddress(), cause.toString());
                ctx.close();
            }
        }
    }

    private static void reply(ChannelHandlerContext ctx, ObjectNode n) {
        if (ctx.channel().isActive()) {
            ctx.writeAndFlush(n.toString() + "\n");
        }
    }
}
