package robosim.hardware;

import picocli.CommandLine.Option;

/** How robots' exchanges with the Environment are threaded (a picocli mixin of robot.sh, robots.sh and headless.sh). */
public final class ExchangeOption {
    /** The threads of a process's exchanges. */
    public enum Threading {
        /** One Hardware Simulator thread per robot sends and receives. */
        ONE_THREAD,
        /** A sending and a receiving thread per robot (the report's two-thread Hardware Simulator). */
        SEND_RECEIVE,
        /** One thread for every robot of the process, in the order they are given (list them in world order). */
        SHARED
    }

    @Option(names = "--exchange", paramLabel = "THREADING",
            description = "The robots' exchange threading: ONE_THREAD (a Hardware Simulator thread per robot; one "
                    + "robot's default), SEND_RECEIVE (a sending and a receiving thread per robot, the report's "
                    + "two-thread Hardware Simulator) or SHARED (one thread for every robot of a process, with "
                    + "--connection PER_ROBOT; the default of robots in one process, fastest as measured in "
                    + "docs/PERFORMANCE.md).")
    private Threading threading;

    /** As given, or null. */
    public Threading given() {
        return threading;
    }

    /** As given, or {@code otherwise}. */
    public Threading or(Threading otherwise) {
        return threading == null ? otherwise : threading;
    }
}
