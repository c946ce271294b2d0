package robosim.runner;

import java.io.IOException;
import picocli.CommandLine.Option;

/** The headless runner's viewers for measuring what viewers cost (a picocli mixin). */
final class ExtraViewerOptions {
    @Option(names = "--live-viewers", defaultValue = "0",
            description = "For measurement: connect this many headless live viewers (default: ${DEFAULT-VALUE}).")
    int liveViewers;

    @Option(names = "--live-viewer-fps", defaultValue = "30",
            description = "Updates a second the --live-viewers ask for, like a Viewer2D window (default: "
                    + "${DEFAULT-VALUE}; 0 = every step).")
    int liveViewerFps;

    @Option(names = "--frozen-viewers", defaultValue = "0",
            description = "For measurement: connect this many viewers that never read (default: ${DEFAULT-VALUE}).")
    int frozenViewers;

    boolean negative() {
        return liveViewers < 0 || frozenViewers < 0 || liveViewerFps < 0;
    }

    ExtraViewers connect(int viewerPort) throws IOException, InterruptedException {
        return ExtraViewers.connect(viewerPort, liveViewers, liveViewerFps, frozenViewers);
    }
}
