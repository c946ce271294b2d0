package robosim.viewer;

import java.util.concurrent.atomic.AtomicReference;
import java.util.function.LongSupplier;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.Traces;
import robosim.protocol.WorldSnapshot;

/**
 * Turns the Environment's snapshot and updates into {@link Scene}s, on the network thread. Trails
 * are kept here in ring buffers ({@link #TRAIL_POINTS} per robot); every update is published at once as a new
 * Scene (with copies): the Environment sends a window at most its frame rate's updates a second
 * ({@code ViewerHello.maxUpdatesPerSecond}), so copying costs per frame, not per step, and the picture is
 * always the newest update's. Changes of the run's state (running, paused, stopped, lost, waiting for the
 * next run) are published at once. A snapshot starts the picture afresh at its step: its world, empty
 * trails, no rate; the next run's (after the end or a lost connection) also starts the run's state afresh,
 * one of the same run (a replay's seek) keeps it. A snapshot of the world shown and more robots (robots
 * joined the running world) keeps the others' trails and the rate. Called by one thread at a time: a
 * session's {@code viewer-client} thread, then, between sessions, the {@link RunFollower}'s.
 */
public final class SceneFeed implements RunFollower.Listener {
    public static final int TRAIL_POINTS = 400;
    /** A trail point is kept only when the robot moved at least this far (mm) since the last one. */
    private static final double TRAIL_SPACING_MM = 20;
    /** The steps per second are measured over at least this long (ns). */
    private static final long RATE_WINDOW_NANOS = 500_000_000L;

    private final AtomicReference<Scene> latest = new AtomicReference<>();
    private final LongSupplier nanoClock;
    private WorldSnapshot world;
    /** The floor's image of {@link #world}, drawn once a snapshot. */
    private java.awt.image.BufferedImage floorImage;
    private double[][] ring;
    private int[] ringStart;
    private int[] ringSize;
    private long rateStep = -1;
    private long rateNanos;
    private double stepsPerSecond = Double.NaN;
    private PoseUpdate poses;
    /** What the world's loop functions have drawn, pieced together from the updates ({@link Traces.Log#apply}). */
    private final Traces.Log drawing = new Traces.Log();
    private ViewedRun status = ViewedRun.of(ViewedRun.Kind.WAITING_FOR_ROBOTS);

    /** {@code nanoClock}: the time the steps per second are measured by, ns ({@code System::nanoTime}). */
    public SceneFeed(LongSupplier nanoClock) {
        this.nanoClock = nanoClock;
    }

    /** The newest scene, or null before the snapshot has arrived. */
    public Scene latest() {
        return latest.get();
    }

    @Override
    public void snapshot(WorldSnapshot snapshot) {
        int n = snapshot.robotNames().size();
        boolean sameRun = world != null && status.kind() != ViewedRun.Kind.STOPPED
                && status.kind() != ViewedRun.Kind.LOST;
        if (sameRun && n > world.robotNames().size()
                && snapshot.robotNames().subList(0, world.robotNames().size()).equals(world.robotNames())) {
            // robots joined the running world: the others keep their trails, the run its state; the steps per second
            // are measured afresh (a replay sought forward across a join looks the same, and its jump is no rate)
            world = snapshot;
            floorImage = Scene.picture(snapshot.scenery().floor().image());
            rateStep = -1;
            stepsPerSecond = Double.NaN;
            ring = java.util.Arrays.copyOf(ring, n);
            for (int i = 0; i < n; i++) {
                ring[i] = ring[i] == null ? new double[2 * TRAIL_POINTS] : ring[i];
            }
            ringStart = java.util.Arrays.copyOf(ringStart, n);
            ringSize = java.util.Arrays.copyOf(ringSize, n);
            publish(drawn(snapshot.poses()));
            return;
        }
        world = snapshot;
        floorImage = Scene.picture(snapshot.scenery().floor().image());
        ring = new double[n][2 * TRAIL_POINTS];
        ringStart = new int[n];
        ringSize = new int[n];
        rateStep = -1;
        stepsPerSecond = Double.NaN;
        if (!sameRun) {
            status = ViewedRun.of(ViewedRun.Kind.WAITING_FOR_ROBOTS);
        }
        drawing.erase();
        PoseUpdate first = drawn(snapshot.poses());
        record(first);
        publish(first);
    }

    @Override
    public void runState(RunState state) {
        status = ViewedRun.of(switch (state.phase()) {
            case WAITING -> ViewedRun.Kind.WAITING_FOR_ROBOTS;
            case RUNNING -> ViewedRun.Kind.RUNNING;
            case PAUSED -> ViewedRun.Kind.PAUSED;
        });
        if (state.phase() == RunState.Phase.RUNNING) {
            rateStep = -1; // measure afresh: the time spent paused is not the run's speed
            stepsPerSecond = Double.NaN;
        }
        if (poses != null) {
            publish(poses);
        }
    }

    @Override
    public void update(PoseUpdate update) {
        PoseUpdate u = drawn(update);
        record(u);
        long now = nanoClock.getAsLong();
        if (rateStep < 0) {
            rateStep = u.step();
            rateNanos = now;
        } else if (now - rateNanos >= RATE_WINDOW_NANOS) {
            stepsPerSecond = (u.step() - rateStep) / ((now - rateNanos) / 1e9);
            rateStep = u.step();
            rateNanos = now;
        }
        publish(u);
    }

    /** The simulation is over: keep the last picture (with the newest poses), say why. */
    @Override
    public void end(SimulationEnd end) {
        status = new ViewedRun(ViewedRun.Kind.STOPPED, end.reason(), "");
        if (poses != null) {
            publish(poses);
        }
    }

    /** The connection broke: keep the last picture, say why. */
    @Override
    public void lost(java.io.IOException cause) {
        status = new ViewedRun(ViewedRun.Kind.LOST, String.valueOf(cause.getMessage()), "");
        if (poses != null) {
            publish(poses);
        }
    }

    /** Between runs: the last picture stays, the status line says what the viewer does meanwhile. */
    @Override
    public void between(String doing) {
        status = status.withNext(doing);
        Scene s = latest.get();
        if (s != null) {
            latest.set(s.withStatus(status));
        }
    }

    /**
     * {@code u} with the whole drawing as of it (its piece applied to what was drawn before; a piece that does not
     * follow, which only a fault sends, starts the drawing afresh at the next whole one). Unchanged without loop
     * functions.
     */
    private PoseUpdate drawn(PoseUpdate u) {
        if (u.lightsOn() == null) {
            return u;
        }
        try {
            drawing.apply(u.traces());
        } catch (robosim.protocol.ProtocolException e) {
            drawing.erase();
        }
        return u.withWholeDrawing(drawing.whole());
    }

    private void record(PoseUpdate u) {
        poses = u;
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

    private void publish(PoseUpdate u) {
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
                stepsPerSecond, status, world.scenery(), floorImage));
    }
}
