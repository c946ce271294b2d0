package robosim.viewer;

import java.util.concurrent.atomic.AtomicReference;
import robosim.protocol.PoseUpdate;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;

/**
 * Turns the Environment's snapshot and updates into {@link Scene}s, on the network thread. Trails
 * are kept here in ring buffers ({@link #TRAIL_POINTS} per robot); a new Scene (with copies) is
 * published at most every {@code frameNanos}, so copying costs per frame, not per step.
 */
public final class SceneFeed implements ViewerClient.Listener {
    public static final int TRAIL_POINTS = 400;
    /** A trail point is kept only when the robot moved at least this far (mm) since the last one. */
    private static final double TRAIL_SPACING_MM = 20;

    private final AtomicReference<Scene> latest = new AtomicReference<>();
    private final long frameNanos;
    private WorldSnapshot world;
    private double[][] ring;
    private int[] ringStart;
    private int[] ringSize;
    private long lastPublish;
    private long rateStep = -1;
    private long rateNanos;
    private double stepsPerSecond;

    public SceneFeed(long frameNanos) {
        this.frameNanos = frameNanos;
    }

    /** The newest scene, or null before the snapshot has arrived. */
    public Scene latest() {
        return latest.get();
    }

    @Override
    public void snapshot(WorldSnapshot snapshot) {
        world = snapshot;
        int n = snapshot.robotNames().size();
        ring = new double[n][2 * TRAIL_POINTS];
        ringStart = new int[n];
        ringSize = new int[n];
        record(snapshot.poses());
        publish(snapshot.poses(), "waiting for robots");
    }

    @Override
    public void update(PoseUpdate u) {
        record(u);
        long now = System.nanoTime();
        if (rateStep < 0) {
            rateStep = u.step();
            rateNanos = now;
        } else if (now - rateNanos >= 500_000_000L) {
            stepsPerSecond = (u.step() - rateStep) / ((now - rateNanos) / 1e9);
            rateStep = u.step();
            rateNanos = now;
        }
        if (now - lastPublish >= frameNanos) {
            publish(u, "running");
            lastPublish = now;
        }
    }

    @Override
    public void end(SimulationEnd end) {
        Scene s = latest.get();
        String status = "simulation over: " + end.reason();
        if (s != null) {
            latest.set(s.withStatus(status));
        }
    }

    /** The connection broke: keep the last picture, say why. */
    @Override
    public void lost(java.io.IOException cause) {
        Scene s = latest.get();
        if (s != null) {
            latest.set(s.withStatus("connection lost: " + cause.getMessage()));
        }
    }

    private void record(PoseUpdate u) {
        for (int i = 0; i < u.count(); i++) {
            int size = ringSize[i];
            if (size > 0) {
                int lastIndex = (ringStart[i] + size - 1) % TRAIL_POINTS;
                double dx = u.xMm(i) - ring[i][2 * lastIndex];
                double dy = u.yMm(i) - ring[i][2 * lastIndex + 1];
                if (dx * dx + dy * dy < TRAIL_SPACING_MM * TRAIL_SPACING_MM) {
                    continue;
                }
            }
            int slot;
            if (size < TRAIL_POINTS) {
                slot = (ringStart[i] + size) % TRAIL_POINTS;
                ringSize[i] = size + 1;
            } else {
                slot = ringStart[i];
                ringStart[i] = (ringStart[i] + 1) % TRAIL_POINTS;
            }
            ring[i][2 * slot] = u.xMm(i);
            ring[i][2 * slot + 1] = u.yMm(i);
        }
    }

    private void publish(PoseUpdate u, String status) {
        double[][] trails = new double[ring.length][];
        for (int i = 0; i < ring.length; i++) {
            double[] t = new double[2 * ringSize[i]];
            for (int p = 0; p < ringSize[i]; p++) {
                int slot = (ringStart[i] + p) % TRAIL_POINTS;
                t[2 * p] = ring[i][2 * slot];
                t[2 * p + 1] = ring[i][2 * slot + 1];
            }
            trails[i] = t;
        }
        latest.set(new Scene(world.arena(), world.obstacles(), world.robotNames(), world.robots(), u, trails,
                stepsPerSecond, status));
    }
}
