package robosim.hardware;

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

    long connectTimeoutMs() {
        return connectTimeoutS * 1000L;
    }
}
