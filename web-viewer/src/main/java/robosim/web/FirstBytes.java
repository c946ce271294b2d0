package robosim.web;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.socket.SocketChannel;
import io.netty.handler.codec.ByteToMessageDecoder;
import io.netty.handler.ssl.SslHandler;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.Greeting;
import robosim.protocol.Protocol;
import robosim.protocol.SimulationEnd;
import robosim.protocol.Tls;
import robosim.protocol.WrongClients;

/**
 * A netty port's first look at a connection, its first handler (the control port's and the web port's): what
 * the client's first bytes say it speaks ({@link Greeting}). A client of the port's own protocol (a line for
 * the control port, HTTP for the web port) goes on to the handlers after this one, and TLS goes on through an
 * {@link SslHandler} when the port has the key pair; anything else is answered in the client's own protocol
 * with what this port is ({@link WrongClients}): a robot, viewer or Geometry process gets a
 * {@link SimulationEnd}, a browser a {@code 400}, a Control Panel a refusal line, and a client of the port's
 * own protocol without TLS at a port that speaks TLS is told so. Inside TLS a second one looks at what the client
 * says there, with the same answers. A client answered (or turned away without a word: TLS at a port without keys,
 * bytes of no protocol) has its further bytes dropped until it closes, or for at most {@value #DRAIN_S} s, so that
 * what it is told is not lost to a reset; it is logged once. Not shared: one per connection; the I/O thread.
 */
public final class FirstBytes extends ByteToMessageDecoder {
    private static final Logger LOG = LoggerFactory.getLogger(FirstBytes.class);
    /** How long an answered client is given to read the answer and close, s. */
    private static final int DRAIN_S = 10;

    private final Tls tls;
    private final Greeting.Kind speaks;
    /** "the Environment's control port (the Control Panel's)" */
    private final String port;
    private boolean answered;

    /**
     * @param tls    the port's TLS, or null
     * @param speaks {@link Greeting.Kind#TEXT} (the control port) or {@link Greeting.Kind#HTTP} (the web port)
     * @param port   what the port is, for the answers: "the Environment's web port (a browser's)"
     */
    public FirstBytes(Tls tls, Greeting.Kind speaks, String port) {
        this.tls = tls;
        this.speaks = speaks;
        this.port = port;
    }

    @Override
    protected void decode(ChannelHandlerContext ctx, ByteBuf in, List<Object> out) {
        if (answered) {
            in.skipBytes(in.readableBytes());
            return;
        }
        if (in.readableBytes() < Greeting.BYTES && in.indexOf(in.readerIndex(), in.writerIndex(), (byte) '\n') < 0) {
            return; // (a line shorter than the greeting ends in its newline)
        }
        byte[] first = new byte[Math.min(Greeting.BYTES, in.readableBytes())];
        in.getBytes(in.readerIndex(), first);
        Greeting.Kind kind = Greeting.of(first).kind();
        if (kind == speaks) {
            if (tls == null) {
                ctx.pipeline().remove(this); // (what it holds goes on to the handlers after it)
            } else if (speaks == Greeting.Kind.HTTP) {
                answer(ctx, in, WrongClients.httpRefusal("this port speaks TLS (tls=on): open it as https://, in a "
                        + "browser that holds the simulation's key pair"), "HTTP without TLS");
            } else {
                answer(ctx, in, WrongClients.lineRefusal("the Environment speaks TLS (tls=on): set ROBOSIM_KEYS to the "
                        + "simulation's keys"), "a line without TLS");
            }
            return;
        }
        switch (kind) {
            case TLS -> {
                if (tls != null) { // (what the client says inside TLS is looked at again, as plain)
                    ctx.pipeline().addAfter(ctx.name(), "tls", new SslHandler(tls.serverEngine()));
                    ctx.pipeline().addAfter("tls", "first-bytes-in-tls", new FirstBytes(null, speaks, port));
                    ctx.pipeline().remove(this);
                } else {
                    answer(ctx, in, new byte[0], "TLS, but this Environment has no keys (tls=off)");
                }
            }
            case OBJECT_STREAM -> answer(ctx, in, WrongClients.objectRefusal(new SimulationEnd(-1, "that is " + port
                    + "; robots, viewers and Geometry use the Environment's own ports (" + Protocol.DEFAULT_ROBOT_PORT
                    + ", " + Protocol.DEFAULT_VIEWER_PORT + " and " + Protocol.DEFAULT_GEOMETRY_PORT + " by default)")),
                    "RoboSim's object protocol (a robot, viewer or Geometry process)");
            case HTTP -> answer(ctx, in, WrongClients.httpRefusal("that is " + port + ", not a web page; the browser "
                    + "viewer is on the web port (--web-port)"), "HTTP");
            case TEXT -> answer(ctx, in, WrongClients.lineRefusal("that is " + port + "; the Control Panel uses the "
                    + "control port (" + Protocol.DEFAULT_CONTROL_PORT + " by default)"), "a line of text");
            default -> answer(ctx, in, new byte[0], "bytes of no protocol this port knows");
        }
    }

    /**
     * Writes {@code answer} (nothing: turned away without a word), shuts the sending side, and drops what the client
     * sends until it closes.
     */
    private void answer(ChannelHandlerContext ctx, ByteBuf in, byte[] answer, String spoke) {
        answered = true;
        in.skipBytes(in.readableBytes());
        LOG.info("{}: {} spoke {}; {}", port, ctx.channel().remoteAddress(), spoke,
                answer.length > 0 ? "told it what this port is" : "closed");
        ctx.writeAndFlush(Unpooled.wrappedBuffer(answer))
                .addListener(f -> ((SocketChannel) ctx.channel()).shutdownOutput());
        ctx.executor().schedule(() -> ctx.close(), DRAIN_S, TimeUnit.SECONDS);
    }
}
