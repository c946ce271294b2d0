package robosim.examples;

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
import io.netty.handler.ssl.SslHandler;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.api.RobotControl;
import robosim.protocol.LineProof;
import robosim.protocol.SimulationKeys;

/**
 * A robot a person or a program drives. Commands are text: {@code forward MM}, {@code back MM},
 * {@code left DEG}, {@code right DEG} (a number may be left out: 250 mm, 15 degrees) and
 * {@code stop} (drop every queued command). They arrive two ways:
 * <ul>
 *   <li>over its own link: it listens on the host and port RobotInfo.xml gives for its name (netty,
 *   one command per line; the Remote Control connects there). The file is the system property
 *   {@code robosim.robotInfo}, else the environment variable {@code ROBOSIM_ROBOT_INFO}, else
 *   {@code test-envs/RobotInfo.xml}. Each command is answered with one line when it is done:
 *   {@code done forward 750 x=... y=... heading=...}, or {@code error ...} at once. With the
 *   simulation's keys ({@code ROBOSIM_KEYS}, see {@link SimulationKeys}) a connection proves the shared
 *   secret first ({@code challenge}, answered {@code nonce HEX}; {@code prove HEX}, answered
 *   {@code proven}) and speaks TLS when they hold the key pair; without TLS the link listens on loopback
 *   only. At most {@link #MAX_CONNECTIONS} connections at once;</li>
 *   <li>as messages from other robots, answered with a message {@code done COMMAND}.</li>
 * </ul>
 * Commands run one at a time in arrival order; between them the robot stands still, checking for new
 * ones every step. At most {@link #QUEUE} may wait; more are refused ("busy").
 */
public final class RemoteControlRobot implements RobotControl {
    private static final Logger LOG = LoggerFactory.getLogger(RemoteControlRobot.class);
    /** Commands that may wait their turn. */
    public static final int QUEUE = 16;
    /** The longest command line, bytes. */
    public static final int MAX_LINE = 256;
    /** Link connections held at once; one more is closed at once. */
    public static final int MAX_CONNECTIONS = 8;
    /** A connection that has not proved the secret this long after connecting is closed, s. */
    public static final int PROOF_DEADLINE_S = 10;

    private record Pending(String command, Channel from) {
    }

    private final BlockingQueue<Pending> queue = new ArrayBlockingQueue<>(QUEUE);
    private final AtomicInteger connections = new AtomicInteger();
    /** The simulation's keys as given, or null to take them from the environment ({@code ROBOSIM_KEYS}). */
    private final SimulationKeys givenKeys;

    /** As a robot process runs it: its keys from the environment. */
    public RemoteControlRobot() {
        this.givenKeys = null;
    }

    /** With these keys (for a robot in a program that holds them). */
    public RemoteControlRobot(SimulationKeys keys) {
        this.givenKeys = keys;
    }

    @Override
    public void run(Robot robot) throws InterruptedException {
        EventLoopGroup group = null;
        try {
            group = listen(robot.name());
            while (true) {
                Pending p = queue.poll();
                if (p != null) {
                    if (execute(robot, p.command())) {
                        reply(p.from(), String.format(Locale.ROOT, "done %s x=%.1f y=%.1f heading=%.1f",
                                p.command(), robot.xMm(), robot.yMm(), robot.headingDeg()));
                    }
                    continue;
                }
                Message m = robot.receive();
                if (m != null) {
                    if (parse(m.text()) != null && execute(robot, m.text())) {
                        robot.send(m.from(), "done " + m.text());
                    }
                    continue;
                }
                robot.sleep(1); // one step standing still, then look again
            }
        } finally {
            if (group != null) {
                group.shutdownGracefully(0, 1, TimeUnit.SECONDS);
            }
        }
    }

    /** Starts the link server if RobotInfo.xml lists this robot; null otherwise (messages only). */
    private EventLoopGroup listen(String name) throws InterruptedException {
        Path file = RobotInfo.configured();
        RobotInfo me;
        try {
            me = RobotInfo.load(file).stream().filter(r -> r.name().equals(name)).findFirst().orElse(null);
        } catch (IllegalArgumentException e) {
            LOG.warn("{}: {}; taking commands by message only", name, e.getMessage());
            return null;
        }
        if (me == null) {
            LOG.warn("{}: not in {}; taking commands by message only", name, file);
            return null;
        }
        SimulationKeys keys;
        InetSocketAddress address;
        try {
            keys = givenKeys != null ? givenKeys : SimulationKeys.fromEnvironment();
            address = new InetSocketAddress(me.host(), me.port());
        } catch (java.io.IOException | IllegalArgumentException e) {
            LOG.error("{}: {}; taking commands by message only", name, e.getMessage());
            return null;
        }
        if (!address.isUnresolved() && !address.getAddress().isLoopbackAddress() && (keys == null || keys.tls() == null)) {
            LOG.error("{}: {} puts its link on {}, beyond this machine: set ROBOSIM_KEYS (scripts/make-keys.sh) for "
                    + "TLS and the shared secret; taking commands by message only", name, file, me.host());
            return null;
        }
        robosim.protocol.Tls tls = keys == null ? null : keys.tls();
        EventLoopGroup group = new NioEventLoopGroup(1);
        try {
            new ServerBootstrap().group(group).channel(NioServerSocketChannel.class)
                    .childHandler(new ChannelInitializer<SocketChannel>() {
                        @Override
                        protected void initChannel(SocketChannel ch) {
                            if (connections.incrementAndGet() > MAX_CONNECTIONS) {
                                connections.decrementAndGet();
                                ch.close();
                                return;
                            }
                            ch.closeFuture().addListener(f -> connections.decrementAndGet());
                            if (tls != null) {
                                ch.pipeline().addLast(new SslHandler(tls.serverEngine()));
                            }
                            ch.pipeline().addLast(new LineBasedFrameDecoder(MAX_LINE, true, true),
                                    new StringDecoder(StandardCharsets.UTF_8), new StringEncoder(StandardCharsets.UTF_8),
                                    new LinkHandler(new LineProof(keys, LineProof.REMOTE_CONTROL)));
                        }
                    }).bind(address).sync();
        } catch (Exception e) {
            group.shutdownGracefully(0, 1, TimeUnit.SECONDS);
            LOG.error("{}: cannot listen on {}:{} from {}: {}; taking commands by message only", name, me.host(),
                    me.port(), file, e.toString());
            return null;
        }
        LOG.info("{}: remote control link on {}:{}", name, me.host(), me.port());
        return group;
    }

    /** Netty's I/O thread: checks each line and queues it for the control thread. */
    private final class LinkHandler extends SimpleChannelInboundHandler<String> {
        private final LineProof proof;

        LinkHandler(LineProof proof) {
            this.proof = proof;
        }

        @Override
        public void channelActive(ChannelHandlerContext ctx) {
            if (!proof.proven()) {
                ctx.executor().schedule(() -> {
                    if (!proof.proven()) {
                        ctx.close();
                    }
                }, PROOF_DEADLINE_S, TimeUnit.SECONDS);
            }
            ctx.fireChannelActive();
        }

        @Override
        protected void channelRead0(ChannelHandlerContext ctx, String line) {
            String[] w = line.strip().split("\\s+", 2);
            if (w[0].equals(LineProof.CHALLENGE)) {
                reply(ctx.channel(), "nonce " + proof.challenge());
                return;
            }
            if (w[0].equals(LineProof.PROVE)) {
                reply(ctx.channel(), proof.prove(w.length > 1 ? w[1] : "") ? "proven"
                        : "error that is not the proof for the last challenge");
                return;
            }
            if (!proof.proven()) {
                reply(ctx.channel(), "error prove the shared secret first: challenge, then prove HEX");
                return;
            }
            String command = parse(line);
            if (command == null) {
                reply(ctx.channel(), "error not a command: \"" + abbreviate(line.strip())
                        + "\" (forward MM, back MM, left DEG, right DEG, stop)");
            } else if (command.equals("stop")) {
                java.util.List<Pending> dropped = new java.util.ArrayList<>();
                queue.drainTo(dropped);
                for (Pending p : dropped) {
                    reply(p.from(), "error cancelled by stop: " + p.command());
                }
                queue.offer(new Pending(command, ctx.channel()));
            } else if (!queue.offer(new Pending(command, ctx.channel()))) {
                reply(ctx.channel(), "error busy: " + QUEUE + " commands are waiting; send stop to clear them");
            }
        }

        @Override
        public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            if (cause instanceof TooLongFrameException) {
                ctx.writeAndFlush("error line longer than " + MAX_LINE + " bytes\n").addListener(ChannelFutureListener.CLOSE);
            } else {
                ctx.close();
            }
        }
    }

    private static void reply(Channel channel, String line) {
        if (channel != null && channel.isActive()) {
            channel.writeAndFlush(line + "\n");
        }
    }

    /** The command in canonical form ("forward 250"), or null if the text is not one. */
    static String parse(String text) {
        String[] w = text.strip().toLowerCase(Locale.ROOT).split("\\s+");
        if (w.length == 0 || w.length > 2) {
            return null;
        }
        double fallback;
        switch (w[0]) {
            case "stop" -> {
                return w.length == 1 ? "stop" : null;
            }
            case "forward", "back" -> fallback = 250;
            case "left", "right" -> fallback = 15;
            default -> {
                return null;
            }
        }
        double v;
        try {
            v = w.length == 2 ? Double.parseDouble(w[1]) : fallback;
        } catch (NumberFormatException e) {
            return null;
        }
        if (!Double.isFinite(v) || v < 0 || v > 100_000) {
            return null;
        }
        return w[0] + " " + (v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v));
    }

    /** Carries out one command; false if it is not one. */
    static boolean execute(Robot robot, String text) throws InterruptedException {
        String command = parse(text);
        if (command == null) {
            return false;
        }
        String[] w = command.split(" ");
        switch (w[0]) {
            case "forward" -> robot.move(Double.parseDouble(w[1]));
            case "back" -> robot.move(-Double.parseDouble(w[1]));
            case "left" -> robot.turn(Double.parseDouble(w[1]));
            case "right" -> robot.turn(-Double.parseDouble(w[1]));
            default -> robot.sleep(1); // stop: the robot already stands still; one step
        }
        return true;
    }

    private static String abbreviate(String s) {
        String clean = s.replaceAll("\\p{Cntrl}", "?");
        return clean.length() > 40 ? clean.substring(0, 40) + "..." : clean;
    }
}
