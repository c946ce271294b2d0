package robosim.sweep;

import java.util.Arrays;
import java.util.BitSet;
import robosim.protocol.Arena;

/**
 * The built-in metrics that add up step by step, as a run goes ({@link RunMetrics} reads them from a recording, a
 * learning environment keeps them live, {@code robosim.rl.BatchWorlds}): the robots' paths ({@code distance_m}),
 * their contacts ({@code contacts}), the messages delivered ({@code messages_delivered}) and the share of the arena's
 * cells a robot's centre has been in ({@code area_covered}). Fed each step's poses and each robot's contact and
 * deliveries; a robot seen for the first time (one that joined) starts its path where it is first seen.
 */
public final class RunTally {
    private final Arena arena;
    private final double cellMm;
    private final int columns;
    private final int rows;
    private final BitSet visited;
    private double[] lastX;
    private double[] lastY;
    private boolean[] touching;
    private double distanceMm;
    private long contacts;
    private long delivered;

    /**
     * A tally of a run in {@code arena}, cells of {@code areaCellM} m, from where its robots stand before the first
     * step ({@code startX}, {@code startY}, mm: those first moves count too).
     *
     * @throws IllegalArgumentException if the cells are too many ({@link RunMetrics#cellProblem})
     */
    public RunTally(Arena arena, double areaCellM, double[] startX, double[] startY) {
        String tooMany = RunMetrics.cellProblem(arena, areaCellM);
        if (tooMany != null) {
            throw new IllegalArgumentException(tooMany);
        }
        this.arena = arena;
        this.cellMm = areaCellM * 1000;
        this.columns = Math.max(1, (int) Math.ceil((arena.maxXMm() - arena.minXMm()) / cellMm));
        this.rows = Math.max(1, (int) Math.ceil((arena.maxYMm() - arena.minYMm()) / cellMm));
        this.visited = new BitSet(columns * rows);
        this.lastX = startX.clone();
        this.lastY = startY.clone();
        this.touching = new boolean[startX.length];
    }

    /** Robot {@code robot} stands at ({@code x}, {@code y}) mm at the end of a step. */
    public void pose(int robot, double x, double y) {
        grow(robot + 1);
        if (!Double.isNaN(lastX[robot])) {
            distanceMm += Math.hypot(x - lastX[robot], y - lastY[robot]);
        }
        lastX[robot] = x;
        lastY[robot] = y;
        int cx = (int) Math.floor((x - arena.minXMm()) / cellMm);
        int cy = (int) Math.floor((y - arena.minYMm()) / cellMm);
        if (cx >= 0 && cx < columns && cy >= 0 && cy < rows) {
            visited.set(cy * columns + cx);
        }
    }

    /** Robot {@code robot} touches something at the end of a step ({@code now}), or not; a new touch is a contact. */
    public void contact(int robot, boolean now) {
        grow(robot + 1);
        if (now && !touching[robot]) {
            contacts++;
        }
        touching[robot] = now;
    }

    /** {@code count} messages were delivered to a robot in a step. */
    public void delivered(int count) {
        delivered += count;
    }

    private void grow(int robots) {
        if (robots > lastX.length) {
            int had = lastX.length;
            lastX = Arrays.copyOf(lastX, robots);
            lastY = Arrays.copyOf(lastY, robots);
            touching = Arrays.copyOf(touching, robots);
            Arrays.fill(lastX, had, robots, Double.NaN);
        }
    }

    public double distanceM() {
        return distanceMm / 1000;
    }

    public long contacts() {
        return contacts;
    }

    public long delivered() {
        return delivered;
    }

    public double areaCovered() {
        return visited.cardinality() / (double) (columns * rows);
    }
}
