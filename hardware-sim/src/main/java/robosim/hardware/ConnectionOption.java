package robosim.hardware;

import picocli.CommandLine.Option;
import robosim.protocol.Limits;

/** How the robots of one process reach the Environment (a picocli mixin of robots.sh and headless.sh). */
public final class ConnectionOption {
    /** One connection for every robot, or one each. */
    public enum Connection {
        /** Each step's requests of every robot in one frame, its responses in one. */
        SHARED,
        /** A connection per robot, threaded as {@code --exchange} says. */
        PER_ROBOT
    }

    @Option(names = "--connection", paramLabel = "KIND",
            description = "How robots in one process connect: SHARED (one connection for every robot, each step's "
                    + "requests in one frame and its responses in one; the default; at most "
                    + Limits.MAX_ROBOTS_PER_CONNECTION + " robots; needs the THREADS or TWO_THREADS coordinator) or "
                    + "PER_ROBOT (a connection per robot, threaded as --exchange says; headless.sh's default with "
                    + "--exchange or --coordinator SEQUENTIAL).")
    private Connection connection;

    /** As given, or null. */
    public Connection given() {
        return connection;
    }
}
