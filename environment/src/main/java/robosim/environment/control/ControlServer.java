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
import io.netty.handler.timeout.WriteTimeoutHandler;
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
import robosim.protocol.SimulationKeys;

/**
 * The control port (netty): one request per line, one JSON reply per line, always in the order of the
 * connection's requests ({@link ControlRequests} says what each does). Requests that wait (step, pause,
 * start, load) run on one {@code control} thread, the others on {@code control-quick}, never on netty's
 * I/O thread ({@code control-io}); a connection has one request in hand at a time, the next starts once
 * its reply has left, and at most {@link #MAX_PIPELINED} wait behind it; nothing more is read from a
 * client that does not take its replies. Bounded: {@link #MAX_LINE} bytes a line (a longer one gets an
 * error and the connection is closed), {@link #MAX_CONNECTIONS} connections at once (one more is closed
 * at once), a connection with nothing in hand that sends no whole request for {@link #IDLE_MINUTES}
 * minutes is closed, and so is one that does not take a reply within {@link #WRITE_TIMEOUT_S} seconds.
 * With keys, every request before the shared secret's proof ({@code challenge}, then {@code prove HEX}) is
 * refused, a connection that has not proved it by the handshake deadline is closed, and with the key pair
 * the port speaks only TLS (mutual, the key pair pinned: see {@link robosim.protocol.Tls}).
 */
public final class ControlServer implements Closeable {
    private static final Logger LOG = LoggerFactory.getLogger(ControlServer.class);
    /** The longest request line, bytes. */
    public static final int MAX_LINE = 4096;
    /** Connections the port holds at once. */
    public static final int MAX_CONNECTIONS = 64;
    /** Requests one connection may have queued behind the one in hand; one more closes it. */
    public static final int MAX_PIPELINED = 32;
    /** A connection with nothing in hand is closed after this long without a whole request, minutes. */
    public static final int IDLE_MINUTES = 5;
    /** A reply the client does not take within this long closes its connection, s. */
    public static final int WRITE_TIMEOUT_S = 30;
    private final ControlRequests requests;
    /** With keys, a connection that has not proved the secret this long after connecting is closed, ms (0: none). */
    private final long proofDeadlineMs;
    /** TLS for every connection, or null (keys without a key pair, or none: loopback only). */
    private final robosim.protocol.Tls tls;
    private final EventLoopGroup group = new NioEventLoopGroup(1,
            (java.util.concurrent.ThreadFactory) r -> named(r, "control-io"));
    /** Requests that wait, one at a time (at most one per connection is ever queued). */
    private final ExecutorService worker = single("control");
    /** Requests that answer at once (status, resume, stop, shutdown), so a long step never holds them up. */
    private final ExecutorService quick = single("control-quick");
    private final AtomicInteger connections = new AtomicInteger();
    private final AtomicInteger refusedSinceLog = new AtomicInteger();
    private final java.util.concurrent.atomic.AtomicLong lastCapLog = new java.util.concurrent.atomic.AtomicLong();
    private Channel server;

    /** Serves {@code commands}; {@code keys} (null: loopback only) proved within {@code proofDeadlineMs} (0: idle only). */
    public ControlServer(ControlCommands commands, SimulationKeys keys, long proofDeadlineMs) {
        this.requests = new ControlRequests(commands, keys);
        this.proofDeadlineMs = proofDeadlineMs;
        this.tls = keys == null ? null : keys.tls();
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
                            refusedOverCap();
                            ch.close();
                            return;
                        }
                        ch.closeFuture().addListener(f -> connections.decrementAndGet());
                        // (TLS, when the client begins it, after it)
                        ch.pipeline().addLast(new robosim.web.FirstBytes(tls, robosim.protocol.Greeting.Kind.TEXT,
                                "the Environment's control port (the Control Panel's)"));
                        // (the idle clock after the decoders: only a whole request line resets it)
                        ch.pipeline().addLast(new WriteTimeoutHandler(WRITE_TIMEOUT_S),
                                new LineBasedFrameDecoder(MAX_LINE, true, true),
                                new StringDecoder(StandardCharsets.UTF_8), new StringEncoder(StandardCharsets.UTF_8),
                                new IdleStateHandler(IDLE_MINUTES, 0, 0, TimeUnit.MINUTES), new Handler());
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

    /** One connection over the cap was closed: says so at most once a second. */
    private void refusedOverCap() {
        int n = refusedSinceLog.incrementAndGet();
        long now = System.nanoTime();
        long last = lastCapLog.get();
        if ((last == 0 || now - last >= TimeUnit.SECONDS.toNanos(1)) && lastCapLog.compareAndSet(last, now)) {
            refusedSinceLog.addAndGet(-n);
            LOG.warn("control port: {} connection(s) closed at once: it holds at most {} at a time", n, MAX_CONNECTIONS);
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
        worker.shutdownNow(); // (a step or pause under way answers "interrupted")
        quick.shutdown(); // the quick requests in hand (a stop, say) answer first, briefly, and their replies leave
        try {
            // (each returns as soon as its requests have answered: 10 s for a loaded machine)
            quick.awaitTermination(10, TimeUnit.SECONDS);
            worker.awaitTermination(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        quick.shutdownNow();
        // the replies those requests handed to the I/O thread leave before this returns (and the process may end):
        // a graceful shutdown runs what is queued, with no quiet period (nobody hands it more: a warm JVM's next run
        // does not wait for one); waited for, at most a few seconds
        group.shutdownGracefully(0, 1000, TimeUnit.MILLISECONDS).awaitUninterruptibly(5_000);
    }

    /** One per connection; its fields are touched on the I/O thread only. */
    private final class Handler extends SimpleChannelInboundHandler<String> {
        private final ControlRequests.Caller caller = requests.caller();
        private final ArrayDeque<String> pending = new ArrayDeque<>();
        /** A request of this connection is being handled or answered; the next starts once its reply is out. */
        private boolean inHand;

        /** The proof deadline, while it runs. */
        private java.util.concurrent.Future<?> proofDeadline;

        @Override
        public void channelInactive(ChannelHandlerContext ctx) {
            if (proofDeadline != null) {
                proofDeadline.cancel(false);
            }
            ctx.fireChannelInactive();
        }

        @Override
        public void channelActive(ChannelHandlerContext ctx) {
            if (!caller.proven() && proofDeadlineMs > 0) {
                proofDeadline = ctx.executor().schedule(() -> {
                    if (!caller.proven() && ctx.channel().isActive()) {
                        LOG.info("control port: {} did not prove the shared secret within {} ms; closing",
                                ctx.channel().remoteAddress(), proofDeadlineMs);
                        ctx.close();
                    }
                }, proofDeadlineMs, TimeUnit.MILLISECONDS);
            }
            ctx.fireChannelActive();
        }

        @Override
        protected void channelRead0(ChannelHandlerContext ctx, String line) {
            String request = line.strip();
            if (request.isEmpty() || !ctx.channel().isActive()) {
                return; // (lines already decoded when the connection was closed below)
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

        /** Starts the next request of this connection, if none is in hand; reads on when none is left. */
        private void next(ChannelHandlerContext ctx) {
            if (inHand) {
                return;
            }
            String request = pending.poll();
            if (request == null) {
                resumeReading(ctx);
                return;
            }
            inHand = true;
            String verb = ControlRequests.verb(request);
            if (!caller.proven() && !ControlRequests.beforeProof(verb)) {
                answered(ctx, ControlReplies.error(ControlRequests.PROVE_FIRST));
                return;
            }
            ExecutorService runner = requests.waits(verb) ? worker : quick;
            try {
                runner.execute(() -> {
                    ObjectNode answer;
                    try {
                        answer = requests.handle(caller, request);
                    } catch (Throwable t) { // the connection's turn must end whatever happens
                        answer = ControlReplies.error("failed: " + t);
                    }
                    ObjectNode a = answer;
                    ctx.executor().execute(() -> answered(ctx, a));
                });
            } catch (RejectedExecutionException e) {
                answered(ctx, ControlReplies.error(runner.isShutdown() ? "the Environment is shutting down"
                        : "the Environment is busy; try again"));
            }
        }

        /** Writes the reply; the next request of this connection starts once it has left (no reply piles up). */
        private void answered(ChannelHandlerContext ctx, ObjectNode answer) {
            if (!ctx.channel().isActive()) {
                pending.clear();
                return;
            }
            ctx.writeAndFlush(answer.toString() + "\n").addListener(f -> {
                inHand = false;
                next(ctx);
            });
        }

        /** Reads on, but only while replies can leave: a client that does not read them gets no more read. */
        private void resumeReading(ChannelHandlerContext ctx) {
            if (ctx.channel().isActive() && ctx.channel().isWritable()) {
                ctx.channel().config().setAutoRead(true);
            }
        }

        @Override
        public void channelWritabilityChanged(ChannelHandlerContext ctx) {
            if (!inHand && pending.isEmpty()) {
                resumeReading(ctx);
            }
            ctx.fireChannelWritabilityChanged();
        }

        @Override
        public void userEventTriggered(ChannelHandlerContext ctx, Object event) {
            if (event instanceof IdleStateEvent && !inHand && pending.isEmpty()) {
                LOG.info("control port: {} sent no request for {} minutes; closing", ctx.channel().remoteAddress(),
                        IDLE_MINUTES);
                ctx.close();
            }
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            if (cause instanceof TooLongFrameException) {
                LOG.warn("control port: {} sent a line over {} bytes; closing", ctx.channel().remoteAddress(), MAX_LINE);
                ctx.writeAndFlush(ControlReplies.error("request longer than " + MAX_LINE + " bytes").toString() + "\n")
                        .addListener(ChannelFutureListener.CLOSE);
            } else {
                LOG.info("control port: {} dropped: {}", ctx.channel().remoteAddress(),
                        ControlReplies.abbreviate(cause.toString(), 120));
                ctx.close();
            }
        }
    }

}
