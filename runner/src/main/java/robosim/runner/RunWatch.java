package robosim.runner;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import robosim.protocol.PoseUpdate;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepNumbers;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;

/**
 * A viewer connection that watches a run: the headless runner's, for {@code --pose-log} (a recording
 * viewer: every step) and {@code --progress} (step and steps/s once a second), and
 * {@code scripts/pose-log.sh}'s. Its listener runs on the {@code viewer-client} thread.
 */
final class RunWatch implements AutoCloseable {
    private final ViewerClient viewer;
    private final PoseLog poseLog;
    private final java.util.concurrent.CountDownLatch snapshot;
    private final boolean[] snapshotCame;

    private RunWatch(ViewerClient viewer, PoseLog poseLog, java.util.concurrent.CountDownLatch snapshot,
            boolean[] snapshotCame) {
        this.viewer = viewer;
        this.poseLog = poseLog;
        this.snapshot = snapshot;
        this.snapshotCame = snapshotCame;
    }

    /**
     * Connects to the viewer port on {@code host}; null when neither a pose log nor progress is asked for.
     *
     * @param steps the run's length for the progress line (0: not known)
     */
    static RunWatch connect(String host, int viewerPort, Path poseLogFile, boolean progress, long steps,
            long connectTimeoutMs, java.nio.file.OpenOption... poseLogOptions) throws IOException, InterruptedException {
        if (poseLogFile == null && !progress) {
            return null;
        }
        PoseLog log = poseLogFile == null ? null : new PoseLog(poseLogFile, poseLogOptions);
        ViewerClient viewer;
        try {
            viewer = ViewerClient.connect(host, viewerPort, poseLogFile != null, connectTimeoutMs);
        } catch (IOException | RuntimeException e) {
            if (log != null) {
                log.close();
            }
            throw e;
        }
        java.util.concurrent.CountDownLatch snapshotSeen = new java.util.concurrent.CountDownLatch(1);
        boolean[] snapshotCame = new boolean[1]; // (written before the latch opens, read after)
        viewer.start(new ViewerClient.Listener() {
            private long lastPrint = System.nanoTime();
            private long lastStep = -1;

            @Override
            public void snapshot(WorldSnapshot snapshot) {
                if (log != null) {
                    log.snapshot(snapshot);
                }
                snapshotCame[0] = true;
                snapshotSeen.countDown();
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
                    System.out.printf(Locale.ROOT, "step %d%s  %.0f steps/s%n", StepNumbers.shown(u.step()),
                            steps > 0 ? "/" + steps : "", rate);
                    lastPrint = now;
                    lastStep = u.step();
                }
            }

            @Override
            public void end(SimulationEnd end) {
                snapshotSeen.countDown(); // (ended before it came)
                if (progress) {
                    System.out.println("simulation over: " + end.reason());
                }
            }

            @Override
            public void lost(IOException cause) {
                snapshotSeen.countDown(); // (lost before it came)
            }
        });
        return new RunWatch(viewer, log, snapshotSeen, snapshotCame);
    }

    /**
     * Waits until the world's snapshot has come (from then on every step reaches this viewer); false if the
     * connection ended before it, or it has not come within {@code seconds}.
     */
    boolean awaitSnapshot(long seconds) throws InterruptedException {
        return snapshot.await(seconds, TimeUnit.SECONDS) && snapshotCame[0];
    }

    /**
     * Waits until the viewer has taken the end of the run (every step of the pose log is written); returns
     * the Environment's reason.
     */
    String awaitEnd(long seconds) throws IOException, InterruptedException {
        return viewer.awaitEnd(seconds, TimeUnit.SECONDS).reason();
    }

    /** Steps written to the pose log so far (0 without one). */
    long poseLogSteps() {
        return poseLog == null ? 0 : poseLog.steps();
    }

    @Override
    public void close() throws IOException {
        viewer.close();
        if (poseLog != null) {
            poseLog.close();
        }
    }
}
