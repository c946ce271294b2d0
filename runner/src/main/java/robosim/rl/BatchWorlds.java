package robosim.rl;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import robosim.environment.core.WorldSpec;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotModels;
import robosim.protocol.RobotProperties;
import robosim.sweep.RunMetrics;

/**
 * K copies of one world ({@link BatchWorld}), stepped together: one call applies every robot's action in every
 * world and leaves what they sensed in flat little-endian arrays, laid out world by world, robot by robot (the
 * learning link's batch, {@link BatchLink}). The worlds are shared out over {@code threads} threads: the caller's
 * (the owner of time: it steps its share, world 0 among them, and waits for the rest) and {@code threads - 1}
 * threads {@code rl-worlds[t]}, which step only while the caller waits. The same seed and the same actions give
 * the same arrays, bit for bit, whatever the threads.
 */
public final class BatchWorlds implements AutoCloseable {
    /** The live metrics of each world, in this order: the built-in metrics of a sweep. */
    public static final List<String> METRICS = RunMetrics.BUILT_IN;
    /** A robot's action: linear velocity (mm/s), rotational velocity (deg/s), then its message's numbers. */
    public static final int VELOCITIES = 2;

    private final WorldSpec spec;
    private final List<RobotProperties> properties;
    private final int robots;
    private final int sonars;
    private final double[] sonarMaxMm;
    private final int repeat;
    private final int messageSize;
    private final boolean randomHeadings;
    private final double areaCellM;
    private final BatchWorld[] worlds;
    private final int threads;
    private final ExecutorService helpers;
    private final Object watchLock = new Object();
    private final byte[] sonar;
    private final byte[] pose;
    private final byte[] contact;
    private final byte[] messages;
    private final byte[] metrics;
    private final byte[] steps;

    /**
     * {@code count} worlds of {@code spec}, each action held {@code repeat} time steps, messages of
     * {@code messageSize} numbers (0: none), headings drawn from each episode's seed if {@code randomHeadings}, the
     * area metric's cells of {@code areaCellM} m, stepped on {@code threads} threads. Every world starts with
     * seed {@code spec.seed() + w}.
     */
    public BatchWorlds(WorldSpec spec, int count, int repeat, int messageSize, boolean randomHeadings, double areaCellM,
            int threads) throws ProtocolException {
        this.spec = spec;
        List<RobotProperties> p = new ArrayList<>();
        int most = 0;
        for (WorldSpec.RobotSpec r : spec.robots()) {
            RobotProperties model = RobotModels.byName(r.type());
            p.add(model);
            most = Math.max(most, model.sonars().size());
        }
        this.properties = List.copyOf(p);
        this.robots = p.size();
        this.sonars = most;
        this.sonarMaxMm = p.stream().mapToDouble(r -> r.sonars().stream().mapToDouble(s -> s.maxRangeMm()).max()
                .orElse(0)).toArray();
        this.repeat = repeat;
        this.messageSize = messageSize;
        this.randomHeadings = randomHeadings;
        this.areaCellM = areaCellM;
        this.sonar = new byte[count * robots * sonars * 4];
        this.pose = new byte[count * robots * 3 * 4];
        this.contact = new byte[count * robots];
        this.messages = new byte[count * robots * robots * messageSize * 4];
        this.metrics = new byte[count * METRICS.size() * 8];
        this.steps = new byte[count * 8];
        this.threads = Math.max(1, Math.min(threads, count));
        AtomicInteger made = new AtomicInteger();
        this.helpers = this.threads == 1 ? null : Executors.newFixedThreadPool(this.threads - 1, r -> {
            Thread t = new Thread(r, "rl-worlds[" + made.incrementAndGet() + "]");
            t.setDaemon(true);
            return t;
        });
        this.worlds = new BatchWorld[count];
        for (int w = 0; w < count; w++) {
            worlds[w] = new BatchWorld(this, w);
        }
        long[] seeds = new long[count];
        boolean[] all = new boolean[count];
        for (int w = 0; w < count; w++) {
            seeds[w] = spec.seed() + w;
            all[w] = true;
        }
        step(null, all, seeds);
    }

    /**
     * One step of every world: world w starts a new episode with {@code seeds[w]} where {@code reset[w]}, else
     * applies its robots' actions ({@code actions}: world by world, robot by robot, {@link #actionFields()} each,
     * already checked: finite, velocities within {@link #limits}).
     */
    public void step(float[] actions, boolean[] reset, long[] seeds) throws ProtocolException {
        List<Future<?>> others = new ArrayList<>(threads - 1);
        for (int t = 1; t < threads; t++) {
            int share = t;
            others.add(helpers.submit(() -> {
                stepShare(share, actions, reset, seeds);
                return null;
            }));
        }
        Throwable failed = null;
        try {
            synchronized (watchLock) { // (world 0 is in this share: a viewer that joins sees it between steps)
                stepShare(0, actions, reset, seeds);
            }
        } catch (ProtocolException | RuntimeException e) {
            failed = e;
        }
        for (Future<?> f : others) {
            try {
                f.get();
            } catch (ExecutionException e) {
                failed = failed == null ? e.getCause() : failed;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                failed = failed == null ? e : failed;
            }
        }
        if (failed instanceof ProtocolException p) {
            throw p;
        }
        if (failed != null) {
            throw new IllegalStateException("a world's step failed: " + failed, failed);
        }
    }

    private void stepShare(int share, float[] actions, boolean[] reset, long[] seeds) throws ProtocolException {
        for (int w = share; w < worlds.length; w += threads) {
            if (reset[w]) {
                worlds[w].reset(seeds[w]);
            } else {
                worlds[w].act(actions, w * robots * actionFields());
            }
        }
    }

    /** Each robot's limits, in world order: {max speed mm/s, max turn deg/s}. */
    public double[][] limits() {
        double[][] out = new double[robots][];
        for (int i = 0; i < robots; i++) {
            out[i] = new double[] {properties.get(i).maxSpeedMmPerS(), properties.get(i).maxTurnDegPerS()};
        }
        return out;
    }

    /** World 0, for a viewer; use it holding {@link #watchLock()} only. */
    BatchWorld watched() {
        return worlds[0];
    }

    /** Held while world 0 steps: whoever holds it sees world 0 between two steps. */
    Object watchLock() {
        return watchLock;
    }

    public int count() {
        return worlds.length;
    }

    public int robots() {
        return robots;
    }

    /** The most sonars of a robot of the world: each robot's row of {@link #sonar()} is this long (0 beyond its own). */
    public int sonars() {
        return sonars;
    }

    /** Robot {@code robot}'s farthest sonar range, mm (0 without sonars). */
    public double sonarMaxMm(int robot) {
        return sonarMaxMm[robot];
    }

    public int actionFields() {
        return VELOCITIES + messageSize;
    }

    public WorldSpec spec() {
        return spec;
    }

    public List<RobotProperties> properties() {
        return properties;
    }

    public int repeat() {
        return repeat;
    }

    public int messageSize() {
        return messageSize;
    }

    boolean randomHeadings() {
        return randomHeadings;
    }

    double areaCellM() {
        return areaCellM;
    }

    /** float32 [worlds][robots][sonars], mm. */
    public byte[] sonar() {
        return sonar;
    }

    /** float32 [worlds][robots][3]: x mm, y mm, heading degrees. */
    public byte[] pose() {
        return pose;
    }

    /** uint8 [worlds][robots]: 1 if the robot touched something in the last action's time steps. */
    public byte[] contact() {
        return contact;
    }

    /** float32 [worlds][robots][robots][messageSize]: the last message each robot heard from each, zeros if none. */
    public byte[] messages() {
        return messages;
    }

    /** float64 [worlds][{@link #METRICS}]: each world's episode so far. */
    public byte[] metrics() {
        return metrics;
    }

    /** int64 [worlds]: time steps since each world's episode began. */
    public byte[] steps() {
        return steps;
    }

    @Override
    public void close() {
        if (helpers != null) {
            helpers.shutdownNow();
        }
    }
}
