package robosim.runner;

import picocli.CommandLine.Option;

/** How a runner watches a simulation to its end (a picocli mixin of headless.sh and pose-log.sh). */
final class WatchOptions {
    @Option(names = "--progress", description = "Print the step and steps/s once a second.")
    private boolean progress;

    @Option(names = "--timeout-s", defaultValue = "0", description = "Give up if the simulation has not ended after "
            + "this long (default: ${DEFAULT-VALUE} = wait for its end).")
    private long timeoutS;

    boolean progress() {
        return progress;
    }

    /** Seconds to wait for the end, 0 for as long as it takes. */
    long timeoutS() {
        return timeoutS;
    }
}
