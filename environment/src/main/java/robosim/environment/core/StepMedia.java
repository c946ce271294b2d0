package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import robosim.devices.RabActuator;
import robosim.devices.RabMessage;
import robosim.devices.RabModel;
import robosim.devices.SensorContext;
import robosim.geometry.WorldQueries;
import robosim.protocol.LedSpec;

/**
 * What robots sense of each other in a step, worked out once a step on first use (not once a reader): an index of
 * the robots by where they stand (a grid of {@link #CELL_MM} cells), through which a camera finds the lit LEDs near
 * it, and the range-and-bearing medium: every message a robot's device sent this step, to every robot whose device of
 * the same model is within the sender's range and, where the model asks, in a line between the two devices clear of
 * anything taller than it, with the distance and bearing as the receiver sees them, nearest first (ties: the sender
 * first in world order). One owner: the thread that steps the world.
 */
final class StepMedia {
    /** The grid's cell side, mm: about a camera's reach, so a query looks at a few cells. */
    static final double CELL_MM = 1000;

    private final EnvironmentMap map;
    private final RobotActuators actuators;
    private final WorldQueries queries;
    /** Each robot's range-and-bearing receiver's model, or null for none (set by the sensing as it equips). */
    private RabModel[] receivers;
    /** Each receiver's most messages a step (its sensor's maxMessages). */
    private int[] caps;
    private double[] radius;
    private double[] height;
    private boolean fresh;
    private final java.util.HashMap<Long, int[]> cells = new java.util.HashMap<>();
    private List<List<RabMessage>> received;

    StepMedia(EnvironmentMap map, RobotActuators actuators, WorldQueries queries, double[] radius, double[] height) {
        this.map = map;
        this.actuators = actuators;
        this.queries = queries;
        this.radius = radius;
        this.height = height;
        this.receivers = new RabModel[radius.length];
        this.caps = new int[radius.length];
        this.turned = new int[radius.length];
        this.cos = new double[radius.length];
        this.sin = new double[radius.length];
    }

    /** The robots' bodies now (after a robot joined or left: a robot gone has radius -infinity). */
    void bodies(double[] radii, double[] heights) {
        radius = radii;
        height = heights;
        receivers = java.util.Arrays.copyOf(receivers, radii.length);
        caps = java.util.Arrays.copyOf(caps, radii.length);
        turned = new int[radii.length];
        cos = new double[radii.length];
        sin = new double[radii.length];
        received = null;
    }

    /** Robot {@code i} hears up to {@code most} range-and-bearing messages of {@code model} a step (null: none). */
    void receiver(int i, RabModel model, int most) {
        receivers[i] = model;
        caps[i] = most;
    }

    /** A new step's world: what was worked out is out of date. */
    void stepped() {
        fresh = false;
        received = null;
        if (++epoch == 0) { // (after 2^32 steps: no robot's old step may pass for this one)
            epoch = 1;
            java.util.Arrays.fill(turned, 0);
        }
    }

    private void index() {
        if (fresh) {
            return;
        }
        cells.clear();
        double[] x = map.xs();
        double[] y = map.ys();
        widest = 0;
        for (int i = 0; i < x.length; i++) {
            if (radius[i] == Double.NEGATIVE_INFINITY) {
                continue; // (gone: no one sees it)
            }
            widest = Math.max(widest, radius[i]);
            long key = key(cell(x[i]), cell(y[i]));
            int[] in = cells.get(key);
            int[] more = in == null ? new int[1] : java.util.Arrays.copyOf(in, in.length + 1);
            more[more.length - 1] = i;
            cells.put(key, more);
        }
        fresh = true;
    }

    /** The widest robot's radius, mm (as of the index). */
    private double widest;
    /** The robots whose bodies may reach a box ({@link #crowd}): {@code crowd[0 .. crowdCount)}. */
    private int[] crowd = new int[0];
    private int crowdCount;

    /**
     * Every robot whose body may reach the box, into {@link #crowd} (from the index's cells; all of them when the box
     * spans much of the world).
     */
    private void crowd(double minX, double maxX, double minY, double maxY) {
        index();
        long x0 = cell(minX - widest);
        long x1 = cell(maxX + widest);
        long y0 = cell(minY - widest);
        long y1 = cell(maxY + widest);
        if (crowd.length < radius.length) {
            crowd = new int[radius.length];
        }
        crowdCount = 0;
        if ((double) (x1 - x0 + 1) * (y1 - y0 + 1) > cells.size()) { // (double: a range of any size)
            for (int[] in : cells.values()) {
                for (int j : in) {
                    crowd[crowdCount++] = j;
                }
            }
            return;
        }
        for (long cx = x0; cx <= x1; cx++) {
            for (long cy = y0; cy <= y1; cy++) {
                int[] in = cells.get(key(cx, cy));
                if (in != null) {
                    for (int j : in) {
                        crowd[crowdCount++] = j;
                    }
                }
            }
        }
    }

    /**
     * Whether the line between robots a and b, both ends at height {@code z}, is clear this step: each pair worked
     * out once a step (the line is the same both ways) in a world of at most {@link #PAIRS_CACHED} robots.
     */
    private boolean sight(int a, int b, double z, double[] x, double[] y) {
        int n = radius.length;
        boolean cached = n <= PAIRS_CACHED && (pairHeight == z || Double.isNaN(pairHeight));
        long pair = (long) Math.min(a, b) * n + Math.max(a, b);
        if (cached) {
            pairHeight = z;
            if ((known[(int) (pair >>> 6)] & (1L << pair)) != 0) {
                return (clear[(int) (pair >>> 6)] & (1L << pair)) != 0;
            }
        }
        int lo = Math.min(a, b); // (the line from the lower-numbered end, whoever asks: one answer both ways)
        int hi = Math.max(a, b);
        crowd(Math.min(x[a], x[b]), Math.max(x[a], x[b]), Math.min(y[a], y[b]), Math.max(y[a], y[b]));
        boolean seen = queries.sight(x[lo], y[lo], z, x[hi], y[hi], z, x, y, radius, height, lo, hi, crowd, crowdCount);
        if (cached) {
            known[(int) (pair >>> 6)] |= 1L << pair;
            if (seen) {
                clear[(int) (pair >>> 6)] |= 1L << pair;
            }
        }
        return seen;
    }

    /** The most robots whose pairs' lines of sight are kept for the step (a bit a pair, twice: 128 KiB at most). */
    static final int PAIRS_CACHED = 1024;
    /** This step's pairs looked at, and which of them were clear; the one height they were looked at. */
    private long[] known = new long[0];
    private long[] clear = new long[0];
    private double pairHeight = Double.NaN;

    /** Forgets the pairs' lines of sight (a new step, or another world). */
    private void forgetPairs() {
        int n = radius.length;
        if (n > PAIRS_CACHED) {
            return;
        }
        int words = (int) (((long) n * n + 63) >>> 6);
        if (known.length != words) {
            known = new long[words];
            clear = new long[words];
        } else {
            java.util.Arrays.fill(known, 0);
            java.util.Arrays.fill(clear, 0);
        }
        pairHeight = Double.NaN;
    }

    private static long cell(double mm) {
        return (long) Math.floor(mm / CELL_MM);
    }

    private static long key(long cx, long cy) {
        return cx * 4_000_003L + cy;
    }

    /** Every robot but {@code i} whose centre may lie within {@code range} of robot i's, in world order. */
    private int[] near(int i, double range) {
        double[] x = map.xs();
        double[] y = map.ys();
        crowd(x[i] - range, x[i] + range, y[i] - range, y[i] + range); // (centres: within range of the box)
        int n = 0;
        int[] out = new int[crowdCount];
        for (int k = 0; k < crowdCount; k++) {
            if (crowd[k] != i) {
                out[n++] = crowd[k];
            }
        }
        out = n == out.length ? out : java.util.Arrays.copyOf(out, n);
        java.util.Arrays.sort(out);
        return out;
    }

    /** The step ({@link #stepped} counts them) each robot's heading's cosine and sine were last worked out in. */
    private int[] turned;
    private double[] cos;
    private double[] sin;
    private int epoch = 1;

    /** Every lit LED of the robots within {@code range} (plus their size) of robot i, to {@code visitor}. */
    void leds(int i, double range, SensorContext.LedVisitor visitor) {
        double[] x = map.xs();
        double[] y = map.ys();
        double[] h = map.headings();
        for (int j : near(i, range + radius[i] + CELL_MM)) {
            int[] colours = actuators.leds(j);
            double dx = x[j] - x[i];
            double dy = y[j] - y[i];
            double reach = range + 2 * Math.max(0, radius[j]);
            if (colours.length == 0 || dx * dx + dy * dy > reach * reach) {
                continue;
            }
            List<LedSpec> where = map.properties(j).leds();
            if (turned[j] != epoch) {
                double r = Math.toRadians(h[j]);
                cos[j] = Math.cos(r);
                sin[j] = Math.sin(r);
                turned[j] = epoch;
            }
            double c = cos[j];
            double s = sin[j];
            for (int k = 0; k < Math.min(colours.length, where.size()); k++) {
                if (colours[k] != 0) {
                    LedSpec l = where.get(k);
                    visitor.led(j, x[j] + l.xMm() * c - l.yMm() * s, y[j] + l.xMm() * s + l.yMm() * c, l.zMm(),
                            colours[k]);
                }
            }
        }
    }

    /**
     * The messages robot {@code i} received this step, nearest first (the lower-numbered sender first at one
     * distance), at most its receiver's cap: worked out for it alone the first time it asks in a step. The senders in
     * range are taken by distance and the line of sight looked at only until the cap is reached, so a crowd in range
     * costs a heap, not a sight line to everyone.
     */
    List<RabMessage> received(int i) {
        if (received == null) {
            received = new ArrayList<>(java.util.Collections.nCopies(receivers.length, null));
            forgetPairs();
            reach = 0;
            for (int s = 0; s < Math.min(receivers.length, actuators.robots()); s++) {
                RabActuator a = actuators.rab(s);
                if (a != null && a.data() != null) {
                    reach = Math.max(reach, a.rangeMm());
                }
            }
        }
        List<RabMessage> heard = received.get(i);
        if (heard == null) {
            heard = heard(i);
            received.set(i, heard);
        }
        return heard;
    }

    /** The farthest any sender's messages carry this step, mm. */
    private double reach;
    /** A receiver's candidates this step: each sender's distance (by sender), and the senders in range, to sort. */
    private double[] distances = new double[0];
    private int[] heap = new int[0];

    private List<RabMessage> heard(int j) {
        RabModel receiver = receivers[j];
        double[] r = radius;
        if (receiver == null || caps[j] == 0 || r[j] == Double.NEGATIVE_INFINITY || reach == 0) {
            return List.of();
        }
        double[] x = map.xs();
        double[] y = map.ys();
        int[] near = near(j, reach);
        if (distances.length < x.length) {
            distances = new double[x.length];
        }
        if (heap.length < near.length) {
            heap = new int[near.length];
        }
        int n = 0;
        for (int s : near) {
            RabActuator sender = s < actuators.robots() ? actuators.rab(s) : null;
            if (sender == null || sender.data() == null || r[s] == Double.NEGATIVE_INFINITY
                    || receiver != sender.model()) { // (a device hears its own model's messages)
                continue;
            }
            double dx = x[s] - x[j];
            double dy = y[s] - y[j];
            double dz = sender.model().heightMm() - receiver.heightMm();
            double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (d < sender.rangeMm()) {
                distances[s] = d; // (by sender: near() gives each once)
                heap[n++] = s;
            }
        }
        for (int k = n / 2 - 1; k >= 0; k--) { // (a heap, nearest on top: taken in order only as far as needed)
            down(k, n);
        }
        List<RabMessage> out = new ArrayList<>(Math.min(n, caps[j]));
        double[] h = map.headings();
        while (n > 0 && out.size() < caps[j]) {
            int s = heap[0];
            heap[0] = heap[--n];
            down(0, n);
            RabActuator sender = actuators.rab(s);
            RabModel model = sender.model();
            boolean seen = !model.occluded() || (model.heightMm() == receiver.heightMm()
                    ? sight(j, s, model.heightMm(), x, y)
                    : queries.sight(x[j], y[j], receiver.heightMm(), x[s], y[s], model.heightMm(), x, y, r, height, j, s));
            if (!seen) {
                continue;
            }
            double bearing = 0;
            if (receiver.bearing()) {
                bearing = Math.toDegrees(Math.atan2(y[s] - y[j], x[s] - x[j])) - h[j];
                bearing = bearing % 360;
                bearing = bearing > 180 ? bearing - 360 : bearing <= -180 ? bearing + 360 : bearing;
            }
            out.add(new RabMessage(distances[s], bearing, sender.data()));
        }
        return out;
    }

    /** Sifts heap slot k down among the first n: the nearer sender above, the lower-numbered at one distance. */
    private void down(int k, int n) {
        int s = heap[k];
        while (2 * k + 1 < n) {
            int c = 2 * k + 1;
            if (c + 1 < n && before(heap[c + 1], heap[c])) {
                c++;
            }
            if (!before(heap[c], s)) {
                break;
            }
            heap[k] = heap[c];
            k = c;
        }
        heap[k] = s;
    }

    private boolean before(int a, int b) {
        return distances[a] < distances[b] || (distances[a] == distances[b] && a < b);
    }
}
