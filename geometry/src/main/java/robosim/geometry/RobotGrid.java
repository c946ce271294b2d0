package robosim.geometry;

import org.locationtech.jts.geom.Envelope;

/**
 * A uniform grid over robot centres, so a query near one robot looks at the robots nearby instead
 * of every robot (1000 robots x 16 sonars would otherwise test 16 million pairs a step). Rebuilt at
 * the start of each step and updated as each robot moves; cells are linked lists in int arrays, so
 * it allocates nothing per step. The bounding box of a step's start positions is divided into about
 * one cell per robot (at least 4 radii wide); robots beyond it are kept in the edge cells, and
 * queries are clamped the same way, so every robot is always found. Callers still test each
 * candidate exactly: the grid only narrows the search.
 */
final class RobotGrid {
    private final int n;
    private final double pad;
    private final int[] next;
    private final int[] prev;
    private final int[] cellOf;
    private int[] head = new int[1];
    private double minX;
    private double minY;
    private double cell = 1;
    private int cols = 1;
    private int rows = 1;
    /** @param maxRadius the largest robot radius: a query box grows by it, since robots are stored by centre */
    RobotGrid(int robots, double maxRadius) {
        this.n = robots;
        this.pad = maxRadius;
        this.next = new int[robots];
        this.prev = new int[robots];
        this.cellOf = new int[robots];
        this.cell = Math.max(4 * maxRadius, 1);
    }

    /** Puts every robot in its cell, sizing the grid to the robots' bounding box. */
    void rebuild(double[] x, double[] y) {
        rebuild(x, y, null);
    }

    /** As {@link #rebuild(double[], double[])}, leaving out robots marked in {@code skip} (may be null). */
    void rebuild(double[] x, double[] y, boolean[] skip) {
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            x0 = Math.min(x0, x[i]);
            y0 = Math.min(y0, y[i]);
            x1 = Math.max(x1, x[i]);
            y1 = Math.max(y1, y[i]);
        }
        if (n > 0) {
            double side = Math.max(x1 - x0, y1 - y0);
            double size = Math.max(Math.max(4 * pad, 1), side / Math.max(1, Math.ceil(Math.sqrt(n))));
            int c = (int) Math.min(1024, Math.floor((x1 - x0) / size) + 1);
            int r = (int) Math.min(1024, Math.floor((y1 - y0) / size) + 1);
            minX = x0;
            minY = y0;
            cell = size;
            cols = c;
            rows = r;
        }
        if (head.length < cols * rows) {
            head = new int[cols * rows];
        }
        java.util.Arrays.fill(head, 0, cols * rows, -1);
        for (int i = 0; i < n; i++) {
            if (skip == null || !skip[i]) {
                insert(i, cellIndex(x[i], y[i]));
            }
        }
    }

    /** Robot i is now at (x, y). */
    void moved(int i, double x, double y) {
        int c = cellIndex(x, y);
        if (c != cellOf[i]) {
            remove(i);
            insert(i, c);
        }
    }

    /**
     * A walk over the cells that may hold a robot overlapping an area: one per thread that queries the
     * grid (the moves, and each thread of the sonar pass), so walks never share state.
     */
    final class Cursor {
        private int c0;
        private int c1;
        private int r1;
        private int col;
        private int row;

        /** Selects the cells that may hold a robot overlapping {@code area}. */
        void select(Envelope area) {
            c0 = clamp((int) Math.floor((area.getMinX() - pad - minX) / cell), cols);
            c1 = clamp((int) Math.floor((area.getMaxX() + pad - minX) / cell), cols);
            int r0 = clamp((int) Math.floor((area.getMinY() - pad - minY) / cell), rows);
            r1 = clamp((int) Math.floor((area.getMaxY() + pad - minY) / cell), rows);
            col = c0 - 1;
            row = r0;
        }

        /** The next selected cell, or -1 when done. */
        int nextCell() {
            if (++col > c1) {
                col = c0;
                if (++row > r1) {
                    return -1;
                }
            }
            return row * cols + col;
        }
    }

    int first(int cellIndex) {
        return head[cellIndex];
    }

    int next(int robot) {
        return next[robot];
    }

    private int cellIndex(double x, double y) {
        int c = clamp((int) Math.floor((x - minX) / cell), cols);
        int r = clamp((int) Math.floor((y - minY) / cell), rows);
        return r * cols + c;
    }

    private static int clamp(int v, int size) {
        return v < 0 ? 0 : v >= size ? size - 1 : v;
    }

    private void insert(int i, int c) {
        cellOf[i] = c;
        prev[i] = -1;
        next[i] = head[c];
        if (head[c] >= 0) {
            prev[head[c]] = i;
        }
        head[c] = i;
    }

    private void remove(int i) {
        int c = cellOf[i];
        if (prev[i] >= 0) {
            next[prev[i]] = next[i];
        } else {
            head[c] = next[i];
        }
        if (next[i] >= 0) {
            prev[next[i]] = prev[i];
        }
    }
}
