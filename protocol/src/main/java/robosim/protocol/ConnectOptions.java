package robosim.protocol;

import picocli.CommandLine.Option;

/** How long a client keeps trying to reach its server, so start order does not matter (a picocli mixin of every client's command line). */
public final class ConnectOptions {
    @Option(names = "--connect-timeout-s", defaultValue = "30",
            description = "Keep trying to connect for this long, so start order does not matter "
                    + "(default: ${DEFAULT-VALUE}).")
    private int seconds;

    public int seconds() {
        return seconds;
    }

    public long millis() {
        return seconds * 1000L;
    }
}
