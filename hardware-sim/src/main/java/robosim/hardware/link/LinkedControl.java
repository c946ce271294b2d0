package robosim.hardware.link;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ClosedByInterruptException;
import java.nio.channels.ServerSocketChannel;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.Robot;
import robosim.api.RobotControl;
import robosim.protocol.link.FirstHello;

/**
 * Control code in another process, attached by hand over the robot link ({@link RobotLink}): the robot listens on
 * loopback, on its parameter {@code link_port} (0 or none: a port the system picks, said in the log), for one
 * controller (a connection whose hello is refused, a stranger's, is answered why and logged, and the port listens
 * on), and serves it until it says bye (the control code returned), reports a failure (it threw) or the
 * simulation ends. An environment file names it as a robot's control class,
 * {@code control="robosim.hardware.link.LinkedControl"}; the controller, started by hand (in a debugger, say), connects
 * within the run's step timeout (the simulation waits for the robot's first call until then).
 */
public final class LinkedControl implements RobotControl {
    private static final Logger LOG = LoggerFactory.getLogger(LinkedControl.class);
    /** Refused connections logged, at most (strangers on this machine may try many). */
    static final int MAX_LOGGED_REFUSALS = 8;
    /** Connections whose hellos are awaited at once (strangers beyond are closed at once). */
    static final int MAX_PENDING = 16;
    /** How long it waits for its controller: until the simulation ends it. */
    private static final long FOREVER_MS = Long.MAX_VALUE / 2_000_000;
    private final ServerSocketChannel given;

    /** Listens on the robot's parameter {@code link_port}. */
    public LinkedControl() {
        this.given = null;
    }

    /** Takes its controller from {@code listening} (bound on loopback by the caller), and closes it. */
    public LinkedControl(ServerSocketChannel listening) {
        this.given = listening;
    }

    @Override
    public void run(Robot robot) throws InterruptedException {
        try (ServerSocketChannel server = given != null ? given : listen(robot)) {
            InetSocketAddress at = (InetSocketAddress) server.getLocalAddress();
            LOG.info("{}: waiting for its controller on {}:{} (the robot link)", robot.name(),
                    at.getAddress().getHostAddress(), at.getPort());
            int[] refused = {0};
            // several hellos read at once (strangers that say nothing hold none of them up), until the controller's;
            // an interrupt (the simulation's end) closes the channel and ends the wait
            FirstHello.Welcomed<RobotLink> controller = FirstHello.await(server.socket(), FOREVER_MS, MAX_PENDING,
                    socket -> RobotLink.welcomed(socket, robot, null), why -> {
                        synchronized (refused) {
                            if (++refused[0] <= MAX_LOGGED_REFUSALS) {
                                LOG.warn("{}: {}; it waits for its controller{}", robot.name(), why,
                                        refused[0] == MAX_LOGGED_REFUSALS ? " (further refusals are not logged)" : "");
                            }
                        }
                    });
            if (controller == null) {
                throw new InterruptedException("the simulation is over");
            }
            controller.link().serve();
        } catch (IOException e) { // (a ClosedByInterruptException among them: the simulation's end)
            if (Thread.currentThread().isInterrupted() || e instanceof ClosedByInterruptException) {
                throw new InterruptedException("the simulation is over");
            }
            throw new IllegalStateException("robot link: " + e.getMessage(), e);
        }
    }

    private static ServerSocketChannel listen(Robot robot) throws IOException {
        double port = robot.parameter("link_port", 0.0);
        if (port < 0 || port > 65_535 || port != Math.rint(port)) {
            throw new IllegalArgumentException("parameter link_port is " + port + ", not a port (0 to 65535)");
        }
        ServerSocketChannel server = ServerSocketChannel.open();
        try {
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), (int) port), MAX_PENDING);
        } catch (IOException e) {
            server.close();
            throw e;
        }
        return server;
    }
}
