package robosim.environment.control;

import com.fasterxml.jackson.databind.ObjectMapper;
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
import io.netty.handler.timeout.ReadTimeoutHandler;
import java.io.Closeable;
import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.net.RunStatus;

/**
 * The control port (netty): one request per line, one JSON object per line in reply
 * ({@code {"ok":true,...}} or {@code {"ok":false,"error":"..."}}). Requests: {@code token SECRET},
 * {@code status}, {@code start}, {@code stop}, {@code pause}, {@code resume}, {@code step N},
 * {@code load FILE}, {@code shutdown}. Requests that wait (step, pause, stop, load) run on one
 * {@code control} thread, in order, never on netty's I/O thread. A malformed request gets an error
 * reply; a line over {@link #MAX_LINE} bytes gets one and the connection is closed; the simulation
 * is never touched by a bad request. With a token set, every request before a correct
 * {@code token} line is refused.
 */
public final class ControlServer implements Closeable {
    private static final Logger LOG = LoggerFactory.getLogger(ControlServer.class);
    /** The longest request line, bytes. */
    public static final int MAX_LINE = 4096;
    /** How long a waiting request (step N) may take before it answers anyway, s. */
    private static final long WAIT_S = 600;
    private static final ObjectMapper JSON = new ObjectMapper();

    private final EnvironmentHost host;
    private final String token;
    private final EventLoopGroup group = new NioEventLoopGroup(1,
            (java.util.concurrent.ThreadFactory) r -> named(r, "control-io"));
    /** Requests that wait (step N, pause, start, load), one at a time, in arrival order. */
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> named(r, "control"));
    /** Requests that answer at once (status, resume, stop, shutdown), so a long step never holds them up. */
    private final ExecutorService quick = Executors.newSingleThreadExecutor(r -> named(r, "control-quick"));
    private Channel server;

    /** @param token required before any other request, or null for none (loopback only) */
    public ControlServer(EnvironmentHost host, String token) {
        this.host = host;
        this.token = token == null || token.isEmpty() ? null : token;
    }

    private static Thread named(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    /** Binds; a port in use is a {@link BindException} naming it. */
    public void start(InetAddress bind, int port) throws IOException {
        ServerBootstrap b = new ServerBootstrap().group(group).channel(NioServerSocketChannel.class)
                .childHandler(new ChannelInitializer<SocketChannel>() {
                    @Override
                    protected void initChannel(SocketChannel ch) {
                        ch.pipeline().addLast(new ReadTimeoutHandler(1, TimeUnit.HOURS),
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

    /** One per connection: holds whether it has given the token. */
    private final class Handler extends SimpleChannelInboundHandler<String> {
        private boolean authorised = token == null;

        @Override
        protected void channelRead0(ChannelHandlerContext ctx, String line) {
            String request = line.strip();
            if (request.isEmpty()) {
                return;
            }
            String verb = request.split("\\s+", 2)[0].toLowerCase(java.util.Locale.ROOT);
            if (!authorised && !verb.equals("token")) {
                reply(ctx, error("a token is required first: token SECRET")); // on the I/O thread: no queueing
                return;
            }
            // one request at a time per connection: read no more until this one is answered
            ctx.channel().config().setAutoRead(false);
            boolean waits = verb.equals("step") || verb.equals("pause") || verb.equals("start") || verb.equals("load");
            (waits ? worker : quick).execute(() -> {
                reply(ctx, handle(request));
                ctx.channel().config().setAutoRead(true);
            });
        }

        private ObjectNode handle(String request) {
            String[] w = request.split("\\s+", 2);
            String verb = w[0].toLowerCase(java.util.Locale.ROOT);
            String arg = w.length > 1 ? w[1].strip() : "";
            try {
                if (verb.equals("token")) {
                    authorised = token == null || MessageDigest.isEqual(token.getBytes(StandardCharsets.UTF_8),
                            arg.getBytes(StandardCharsets.UTF_8));
                    if (!authorised) {
                        LOG.warn("control port: a wrong token was given");
                    }
                    return authorised ? ok("authorised") : error("wrong token");
                }
                if (!authorised) {
                    return error("a token is required first: token SECRET");
                }
                return switch (verb) {
                    case "status" -> status();
                    case "start" -> ok(host.start());
                    case "resume" -> {
                        host.current().resume();
                        yield ok("running");
                    }
                    case "pause" -> {
                        host.current().pause(WAIT_S, TimeUnit.SECONDS);
                        yield ok("paused at step " + host.current().status().step());
                    }
                    case "step" -> {
                        long n = steps(arg);
                        long at = host.current().step(n, WAIT_S, TimeUnit.SECONDS);
                        yield ok("paused at step " + at);
                    }
                    case "stop" -> ok(host.stop());
                    case "load" -> {
                        if (arg.isEmpty()) {
                            yield error("load needs a file: load FILE");
                        }
                        yield ok(host.load(Path.of(arg)));
                    }
                    case "shutdown" -> ok(host.shutdown());
                    default -> error("unknown request \"" + abbreviate(verb) + "\" (requests: status, start, stop, "
                            + "pause, resume, step N, load FILE, shutdown, token SECRET)");
                };
            } catch (EnvironmentFileException e) {
                return error(e.getMessage());
            } catch (IllegalArgumentException e) {
                return error(e.getMessage());
            } catch (IOException e) {
                return error(e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return error("interrupted");
            } catch (RuntimeException e) {
                LOG.warn("control port: {} failed", abbreviate(request), e);
                return error("failed: " + e);
            }
        }

        private long steps(String arg) {
            try {
                long n = Long.parseLong(arg);
                if (n < 1) {
                    throw new NumberFormatException();
                }
                return n;
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("step needs a positive whole number of steps, got \""
                        + abbreviate(arg) + "\"");
            }
        }

        private ObjectNode status() {
            RunStatus s = host.current().status();
            ObjectNode n = ok(null);
            n.put("state", s.state().name());
            n.put("step", s.step());
            n.put("steps_per_s", Math.round(s.stepsPerSecond() * 10) / 10.0);
            n.put("file", String.valueOf(host.file()));
            n.putPOJO("robots", s.robots());
            n.putPOJO("connected", s.connected());
            n.putPOJO("left", s.left());
            n.put("geometry", s.geometry());
            n.put("viewers", s.viewers());
            if (!s.reason().isEmpty()) {
                n.put("reason", s.reason());
            }
            return n;
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            if (cause instanceof TooLongFrameException) {
                LOG.warn("control port: {} sent a line over {} bytes; closing", ctx.channel().remoteAddress(), MAX_LINE);
                ctx.writeAndFlush(error("request longer than " + MAX_LINE + " bytes").toString() + "\n")
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

    private static ObjectNode ok(String message) {
        ObjectNode n = JSON.createObjectNode();
        n.put("ok", true);
        if (message != null) {
            n.put("message", message);
        }
        return n;
    }

    private static ObjectNode error(String message) {
        ObjectNode n = JSON.createObjectNode();
        n.put("ok", false);
        n.put("error", message);
        return n;
    }

    private static String abbreviate(String s) {
        String clean = s.replaceAll("\\p{Cntrl}", "?");
        return clean.length() > 40 ? clean.substring(0, 40) + "..." : clean;
    }
}
