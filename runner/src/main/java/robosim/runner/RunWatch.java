package robosim.runner;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import robosim.protocol.PoseUpdate;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;

/**
 * The headless runner's own viewer connection, for {@code --pose-log} (a recording viewer: every
 * step) and {@code --progress} (step and steps/s once a second). Its listener runs on the
 * {@code viewer-client} thread.
 */
final class RunWatch implements AutoCloseable {
    private final ViewerClient viewer;
    private final PoseLog poseLog;

    private RunWatch(ViewerClient viewer, PoseLog poseLog) {
        this.viewer = viewer;
        this.poseLog = poseLog;
    }

    /** Connects to the viewer port; null when neither a pose log nor progress is asked for. */
    static RunWatch connect(int viewerPort, Path poseLogFile, boolean progress, long steps)
            throws IOException, InterruptedException {
        if (poseLogFile == null && !progress) {
            return null;
        }
        PoseLog log = poseLogFile == null ? null : new PoseLog(poseLogFile);
        ViewerClient viewer = ViewerClient.connect("127.0.0.1", viewerPort, poseLogFile != null, 10_000);
        viewer.start(new ViewerClient.Listener() {
            private long lastPrint = System.nanoTime();
            private long lastStep = -1;

            @Override
            public void snapshot(WorldSnapshot snapshot) {
                if (log != null) {
                    log.snapshot(snapshot);
                }
            }

            @Override
            public void update(PoseUpdate u) {
                if (log != null) {
                    log.update(u);
                }
                long now = System.nanoTime();
                if (lastStep < 0) {
                    lastPrint = now;
                    lastStep = u.step();
                } else if (progress && now - lastPrint >= 1_000_000_000L) {
                    double rate = (u.step() - lastStep) / ((now - lastPrint) / 1e9);
                    System.out.printf(Locale.ROOT, "step %d/%d  %.0f steps/s%n", u.step() + 1, steps, rate);
                    lastPrint = now;
                    lastStep = u.step();
                }
            }

            @Override
            public void end(SimulationEnd end) {
                if (progress) {
                    System.out.println("simulation over: " + end.reason());
                }
            }
        });
        return new RunWatch(viewer, log);
    }

    /** Waits until the viewer has taken the end of the run (every step of the pose log is written). */
    void awaitEnd(long seconds) throws IOException, InterruptedException {
        viewer.awaitEnd(seconds, TimeUnit.SECONDS);
    }

    @Override
    public void close() throws IOException {
        viewer.close();
        if (poseLog != null) {
            poseLog.close();
        }
    }
}
