package robosim.hardware;

import java.util.concurrent.atomic.AtomicBoolean;
import picocli.CommandLine.Option;
import robosim.protocol.ObjectConnection;

/** Connection options shared by the robot command lines (a picocli mixin). */
final class ConnectOptions {
    @Option(names = "--connect-timeout-s", defaultValue = "30",
            description = "Keep trying to connect for this long (default: ${DEFAULT-VALUE}).")
    int connectTimeoutS;

    @Option(names = "--reset-every", defaultValue = "" + ObjectConnection.DEFAULT_RESET_EVERY,
            description = "Messages between object-stream resets (default: ${DEFAULT-VALUE}).")
    int resetEvery;

    private final AtomicBoolean toldWaiting = new AtomicBoolean();

    long connectTimeoutMs() {
        return connectTimeoutS * 1000L;
    }

    /** Prints the "connecting to HOST:PORT ..." line once per process, however many robots wait. */
    void waiting(String line) {
        if (toldWaiting.compareAndSet(false, true)) {
            System.err.println(line);
        }
    }
}
