package robosim.environment.control;

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
import robosim.protocol.SimulationEnd;
import robosim.protocol.Tls;
import robosim.protocol.WrongClients;

/**
 * The control port's first look at a connection, its first handler: what the client's first bytes say it
 * speaks ({@link Greeting}). A line (the Control Panel's) goes on to the line handlers, TLS through an
 * {@link SslHandler} when the port has the key pair; anything else is answered in the client's own protocol
 * with what this port is ({@link WrongClients}): a robot, viewer or Geometry process gets a
 * {@link SimulationEnd}, a browser a {@code 400}, a Control Panel without keys at a port that speaks TLS a
 * line saying to set ROBOSIM_KEYS. A client answered so has its further bytes dropped until it closes, or
 * for at most {@value #DRAIN_S} s. The I/O thread only.
 */
final class FirstBytes extends ByteToMessageDecoder {
    private static final Logger LOG = LoggerFactory.getLogger(FirstBytes.class);
    /** How long an answered client is given to read the answer and close, s. */
    private static final int DRAIN_S = 10;
    /** What this port says to a client of RoboSim's object protocol. */
    static final String TO_OBJECT_CLIENTS = "that is the Environment's control port (the Control Panel's); robots, "
            + "viewers and Geometry use the Environment's own ports (8000, 3000 and 10000 by default)";

    /** The port's TLS, or null. */
    private final Tls tls;
    private boolean answered;

    FirstBytes(Tls tls) {
        this.tls = tls;
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
        Greeting greeting = Greeting.of(first);
        switch (greeting.kind()) {
            case TEXT -> {
                if (tls == null) {
                    ctx.pipeline().remove(this); // (what it holds goes on to the line handlers)
                } else {
                    answer(ctx, in, WrongClients.lineRefusal("the Environment speaks TLS (tls=on): set ROBOSIM_KEYS to "
                            + "the simulation's keys"), "a line without TLS");
                }
            }
            case TLS -> {
                if (tls != null) {
                    ctx.pipeline().addAfter(ctx.name(), "tls", new SslHandler(tls.serverEngine()));
                    ctx.pipeline().remove(this);
                } else {
                    LOG.info("control port: {} began TLS, but this Environment has no keys (tls=off); closed",
                            ctx.channel().remoteAddress());
                    ctx.close();
                }
            }
            case OBJECT_STREAM -> answer(ctx, in, WrongClients.objectRefusal(new SimulationEnd(-1, TO_OBJECT_CLIENTS)),
                    "RoboSim's object protocol (a robot, viewer or Geometry process)");
            case HTTP -> answer(ctx, in, WrongClients.httpRefusal("that is the Environment's control port, a line "
                    + "protocol for the Control Panel; the browser viewer is on the web port (--web-port)"), "HTTP");
            default -> {
                LOG.info("control port: {} sent bytes of no protocol this port knows; closed",
                        ctx.channel().remoteAddress());
                ctx.close();
            }
        }
    }

    /** Writes {@code answer}, shuts the sending side, and drops what the client sends until it closes. */
    private void answer(ChannelHandlerContext ctx, ByteBuf in, byte[] answer, String spoke) {
        answered = true;
        in.skipBytes(in.readableBytes());
        LOG.info("control port: {} spoke {}; told it what this port is", ctx.channel().remoteAddress(), spoke);
        ctx.writeAndFlush(Unpooled.wrappedBuffer(answer))
                .addListener(f -> ((SocketChannel) ctx.channel()).shutdownOutput());
        ctx.executor().schedule(() -> {
            ctx.close();
        }, DRAIN_S, TimeUnit.SECONDS);
    }
}
