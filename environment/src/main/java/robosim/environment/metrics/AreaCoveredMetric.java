package robosim.environment.metrics;

import com.google.auto.service.AutoService;
import java.util.BitSet;
import robosim.protocol.Arena;

/**
 * {@code area_covered}: the share of the arena's square cells (side {@link RunStart#areaCellM()}) a robot's centre
 * has been in at the end of some step, 0 to 1. An arena of more than {@link #MAX_CELLS} cells of that side is not
 * counted (NaN; a sweep refuses it up front, {@link #cellProblem}).
 */
@AutoService(StepMetric.class)
public final class AreaCoveredMetric extends StepMetric {
    /** The side of the cells unless a sweep says otherwise, m. */
    public static final double DEFAULT_CELL_M = 0.5;
    /** The most cells counted (one bit each). */
    public static final long MAX_CELLS = 1L << 26;

    private Arena arena;
    private double cellMm;
    private int columns;
    private int rows;
    private BitSet visited;

    public AreaCoveredMetric() {
        super(new MetricInfo("area_covered", "share of the arena, 0 to 1", MetricInfo.Interval.BOOTSTRAP, 50,
                "the share of the arena's square cells (side: the sweep's area-cell-m, default " + DEFAULT_CELL_M
                        + " m) a robot's centre has been in at the end of some step"));
    }

    /** Why cells of {@code cellM} are too many for {@code arena}, or null. */
    public static String cellProblem(Arena arena, double cellM) {
        double cells = Math.ceil((arena.maxXMm() - arena.minXMm()) / (cellM * 1000))
                * Math.ceil((arena.maxYMm() - arena.minYMm()) / (cellM * 1000));
        return cells <= MAX_CELLS ? null : "area cells of " + cellM + " m make " + (long) cells + " cells of this "
                + "arena, at most " + MAX_CELLS;
    }

    @Override
    public void begin(RunStart run) {
        arena = run.arena();
        if (cellProblem(arena, run.areaCellM()) != null) {
            visited = null;
            return;
        }
        cellMm = run.areaCellM() * 1000;
        columns = Math.max(1, (int) Math.ceil((arena.maxXMm() - arena.minXMm()) / cellMm));
        rows = Math.max(1, (int) Math.ceil((arena.maxYMm() - arena.minYMm()) / cellMm));
        visited = new BitSet(columns * rows);
    }

    @Override
    public void step(StepView step) {
        if (visited == null) {
            return;
        }
        for (int r = 0; r < step.robots(); r++) {
            int cx = (int) Math.floor((step.xMm(r) - arena.minXMm()) / cellMm);
            int cy = (int) Math.floor((step.yMm(r) - arena.minYMm()) / cellMm);
            if (cx >= 0 && cx < columns && cy >= 0 && cy < rows) {
                visited.set(cy * columns + cx);
            }
        }
    }

    @Override
    public double value() {
        return visited == null ? Double.NaN : visited.cardinality() / (double) (columns * rows);
    }
}
