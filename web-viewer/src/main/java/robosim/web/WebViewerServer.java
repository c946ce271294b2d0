package robosim.web;

import io.netty.bootstrap.ServerBootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.WriteBufferWaterMark;
import io.netty.channel.nio.NioEventLoopGroup;
import io.netty.channel.socket.SocketChannel;
import io.netty.channel.socket.nio.NioServerSocketChannel;
import io.netty.handler.codec.http.HttpObjectAggregator;
import io.netty.handler.codec.http.HttpServerCodec;
import io.netty.handler.codec.http.websocketx.WebSocketServerProtocolHandler;
import io.netty.handler.timeout.ReadTimeoutHandler;
import io.netty.handler.timeout.WriteTimeoutHandler;
import java.io.Closeable;
import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.SimulationKeys;
import robosim.protocol.Tls;

/**
 * The browser viewer ({@code --web-port} on the Environment and on {@code replay.sh}): a page over HTTP
 * and its feed over a WebSocket ({@code /ws}). Without keys on loopback only; with the simulation's key
 * pair over TLS, on any address, to browsers that hold that key pair (mutual TLS, as every other port:
 * the browser imports {@code simulation.p12}). Bounded:
 * {@link #MAX_CONNECTIONS} connections, one request in hand a page, {@link #MAX_REQUEST} bytes a request, {@link #REQUEST_TIMEOUT_S} s to
 * send one (or open the WebSocket), {@link #MAX_FRAME} bytes a
 * frame from a page, a reply a page does not take within {@link #WRITE_TIMEOUT_S} s closes it; without TLS a
 * Host header that is not this machine's (DNS rebinding), and always a WebSocket from another origin, are refused.
 * Threads: {@code web-io} (netty's I/O), {@code web-status} (a page's status requests), {@code web-commands}
 * (its other requests: pause, seek...),
 * {@code web-feed} ({@link WebFeed}) and the feed's {@code viewer-client}, and for each robot a page watches
 * {@code web-watch-N} and its {@code viewer-client} ({@link WatchFeeds}).
 */
public final class WebViewerServer implements Closeable {
    private static final Logger LOG = LoggerFactory.getLogger(WebViewerServer.class);
    public static final int MAX_CONNECTIONS = 64;
    static final int MAX_REQUEST = 8 * 1024;
    static final int MAX_FRAME = 4 * 1024;
    static final int WRITE_TIMEOUT_S = 30;
    /** A connection that has not sent a whole request (or opened its WebSocket) within this long is closed, s. */
    static final int REQUEST_TIMEOUT_S = 30;

    private final WebClients clients;
    private final StaticFiles files = new StaticFiles();
    private final WebFeed feed;
    private final WatchFeeds watchFeeds;
    /** TLS with the simulation's key pair (with keys), or null: plain HTTP on loopback. */
    private final Tls tls;
    private final WebCommands commands;
    private final EventLoopGroup group = new NioEventLoopGroup(1,
            (java.util.concurrent.ThreadFactory) r -> named(r, "web-io"));
    private final ExecutorService commandThread = single("web-commands");
    private final ExecutorService statusThread = single("web-status");
    private final AtomicInteger connections = new AtomicInteger();
    private Channel server;

    /**
     * @param viewerHost where the viewer port of the Environment or replay in this process listens
     * @param viewerPort that port
     * @param keys its keys, if it has them (the feed proves them like any viewer)
     * @param commands what a page may ask of it
     */
    public WebViewerServer(String viewerHost, int viewerPort, SimulationKeys keys, WebCommands commands) {
        this(viewerHost, viewerPort, keys, tlsOf(keys), commands);
    }

    /** (Checks the keys before any field - an event loop, executors - is made, so a refusal leaks nothing.) */
    private WebViewerServer(String viewerHost, int viewerPort, SimulationKeys keys, Tls tls, WebCommands commands) {
        this.tls = tls;
        this.feed = new WebFeed(viewerHost, viewerPort, keys);
        this.watchFeeds = new WatchFeeds(viewerHost, viewerPort, keys);
        this.clients = new WebClients(group.next(), feed::start, watchFeeds);
        this.commands = commands;
    }

    /** The keys' TLS (null without keys); a shared secret without the key pair is refused. */
    private static Tls tlsOf(SimulationKeys keys) {
        if (keys != null && keys.tls() == null) {
            throw new IllegalArgumentException("the browser viewer needs the simulation's key pair, not a shared secret "
                    + "alone (scripts/make-keys.sh): a browser proves itself by TLS with it");
        }
        return keys == null ? null : keys.tls();
    }

    private static Thread named(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    /** One thread, {@code name}, with a queue of one request per page at most. */
    private static ExecutorService single(String name) {
        return new ThreadPoolExecutor(1, 1, 0, TimeUnit.MILLISECONDS, new ArrayBlockingQueue<>(MAX_CONNECTIONS),
                r -> named(r, name));
    }

    /**
     * Binds {@code port} on {@code bind} (without keys: loopback only); the feed starts with the first page.
     *
     * @throws IOException naming the port if it cannot listen (a port in use: a {@link BindException})
     */
    public void start(InetAddress bind, int port) throws IOException {
        if (tls == null && !bind.isLoopbackAddress()) {
            close();
            throw new IOException("web port " + port + ": beyond loopback only with the simulation's keys (ROBOSIM_KEYS)");
        }
        ServerBootstrap b = new ServerBootstrap().group(group).channel(NioServerSocketChannel.class)
                .childOption(ChannelOption.WRITE_BUFFER_WATER_MARK, new WriteBufferWaterMark(64 * 1024, 256 * 1024))
                .childHandler(new ChannelInitializer<SocketChannel>() {
                    @Override
                    protected void initChannel(SocketChannel ch) {
                        if (connections.incrementAndGet() > MAX_CONNECTIONS) {
                            connections.decrementAndGet();
                            ch.close();
                            return;
                        }
                        ch.closeFuture().addListener(f -> connections.decrementAndGet());
                        // (TLS, the browser showing the key pair, after it when the browser begins it)
                        ch.pipeline().addLast(new FirstBytes(tls, robosim.protocol.Greeting.Kind.HTTP,
                                "the Environment's web port (a browser's)"));
                        ch.pipeline().addLast(new ReadTimeoutHandler(REQUEST_TIMEOUT_S), // (off once a page's socket is open)
                                new WriteTimeoutHandler(WRITE_TIMEOUT_S), new HttpServerCodec(),
                                new HttpObjectAggregator(MAX_REQUEST), new HttpGate(files, tls != null),
                                new WebSocketServerProtocolHandler("/ws", null, false, MAX_FRAME),
                                new PageSocket(clients, commands, commandThread, statusThread));
                    }
                });
        try {
            server = b.bind(new InetSocketAddress(bind, port)).sync().channel();
        } catch (Exception e) {
            close();
            if (e instanceof BindException) {
                throw new BindException("web port " + port + " is already in use");
            }
            throw new IOException("cannot listen on web port " + port + ": " + e.getMessage(), e);
        }
        LOG.info("web viewer on {}://{}:{}/", tls == null ? "http" : "https",
                bind.isAnyLocalAddress() || bind.isLoopbackAddress() ? "localhost" : bind.getHostAddress(), port());
    }

    public int port() {
        return ((InetSocketAddress) server.localAddress()).getPort();
    }

    @Override
    public void close() {
        feed.close();
        watchFeeds.closeAll();
        if (server != null) {
            server.close();
        }
        commandThread.shutdownNow();
        statusThread.shutdownNow();
        group.shutdownGracefully(0, 1, TimeUnit.SECONDS);
    }
}
