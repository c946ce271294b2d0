package robosim.environment.core;

import java.util.ArrayList;
import java.util.Comparator;
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
    }

    /** The robots' bodies now (after a robot joined or left: a robot gone has radius -infinity). */
    void bodies(double[] radii, double[] heights) {
        radius = radii;
        height = heights;
        receivers = java.util.Arrays.copyOf(receivers, radii.length);
    }

    /** Robot {@code i} hears range-and-bearing messages of {@code model} (null: none). */
    void receiver(int i, RabModel model) {
        receivers[i] = model;
    }

    /** A new step's world: what was worked out is out of date. */
    void stepped() {
        fresh = false;
        received = null;
    }

    private void index() {
        if (fresh) {
            return;
        }
        cells.clear();
        double[] x = map.xs();
        double[] y = map.ys();
        for (int i = 0; i < x.length; i++) {
            if (radius[i] == Double.NEGATIVE_INFINITY) {
                continue; // (gone: no one sees it)
            }
            long key = key(cell(x[i]), cell(y[i]));
            int[] in = cells.get(key);
            int[] more = in == null ? new int[1] : java.util.Arrays.copyOf(in, in.length + 1);
            more[more.length - 1] = i;
            cells.put(key, more);
        }
        fresh = true;
    }

    private static long cell(double mm) {
        return (long) Math.floor(mm / CELL_MM);
    }

    private static long key(long cx, long cy) {
        return cx * 4_000_003L + cy;
    }

    /** Every robot but {@code i} whose centre may lie within {@code range} of robot i's, in world order. */
    private List<Integer> near(int i, double range) {
        index();
        double[] x = map.xs();
        double[] y = map.ys();
        long x0 = cell(x[i] - range);
        long x1 = cell(x[i] + range);
        long y0 = cell(y[i] - range);
        long y1 = cell(y[i] + range);
        List<Integer> out = new ArrayList<>();
        if ((x1 - x0 + 1) * (y1 - y0 + 1) > 4L * cells.size()) { // (a reach over much of the world: every robot)
            for (int[] in : cells.values()) {
                for (int j : in) {
                    out.add(j);
                }
            }
        } else {
            for (long cx = x0; cx <= x1; cx++) {
                for (long cy = y0; cy <= y1; cy++) {
                    int[] in = cells.get(key(cx, cy));
                    if (in != null) {
                        for (int j : in) {
                            out.add(j);
                        }
                    }
                }
            }
        }
        out.remove(Integer.valueOf(i));
        out.sort(null);
        return out;
    }

    /** Every lit LED of the robots within {@code range} (plus their size) of robot i, to {@code visitor}. */
    void leds(int i, double range, SensorContext.LedVisitor visitor) {
        double[] x = map.xs();
        double[] y = map.ys();
        double[] h = map.headings();
        for (int j : near(i, range + radius[i] + CELL_MM)) {
            int[] colours = actuators.leds(j);
            if (colours.length == 0 || Math.hypot(x[j] - x[i], y[j] - y[i]) > range + 2 * Math.max(0, radius[j])) {
                continue;
            }
            List<LedSpec> where = map.properties(j).leds();
            double c = Math.cos(Math.toRadians(h[j]));
            double s = Math.sin(Math.toRadians(h[j]));
            for (int k = 0; k < Math.min(colours.length, where.size()); k++) {
                if (colours[k] != 0) {
                    LedSpec l = where.get(k);
                    visitor.led(j, x[j] + l.xMm() * c - l.yMm() * s, y[j] + l.xMm() * s + l.yMm() * c, l.zMm(),
                            colours[k]);
                }
            }
        }
    }

    /** The messages robot {@code i} received this step, nearest first. */
    List<RabMessage> received(int i) {
        if (received == null) {
            received = medium();
        }
        return received.get(i);
    }

    private List<List<RabMessage>> medium() {
        int n = receivers.length;
        List<List<RabMessage>> heard = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            heard.add(new ArrayList<>());
        }
        double[] x = map.xs();
        double[] y = map.ys();
        double[] h = map.headings();
        double[] r = radius;
        for (int s = 0; s < n; s++) {
            RabActuator sender = s < actuators.robots() ? actuators.rab(s) : null;
            if (sender == null || sender.data() == null || r[s] == Double.NEGATIVE_INFINITY) {
                continue;
            }
            RabModel model = sender.model();
            for (int j : near(s, sender.rangeMm())) {
                RabModel receiver = receivers[j];
                if (receiver == null || receiver.bytes() != model.bytes() || r[j] == Double.NEGATIVE_INFINITY) {
                    continue;
                }
                double dx = x[s] - x[j];
                double dy = y[s] - y[j];
                double dz = model.heightMm() - receiver.heightMm();
                double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                if (d >= sender.rangeMm() || (model.occluded() && !queries.sight(x[j], y[j], receiver.heightMm(), x[s],
                        y[s], model.heightMm(), x, y, r, height, j, s))) {
                    continue;
                }
                double bearing = 0;
                if (receiver.bearing()) {
                    bearing = Math.toDegrees(Math.atan2(dy, dx)) - h[j];
                    bearing = bearing % 360;
                    bearing = bearing > 180 ? bearing - 360 : bearing <= -180 ? bearing + 360 : bearing;
                }
                heard.get(j).add(new RabMessage(d, bearing, sender.data()));
            }
        }
        for (List<RabMessage> list : heard) {
            list.sort(Comparator.comparingDouble(RabMessage::rangeMm)); // (stable: the sender first in world order)
        }
        return heard;
    }
}
