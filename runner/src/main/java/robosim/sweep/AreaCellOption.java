package robosim.sweep;

import picocli.CommandLine.Option;

/** The side of the cells {@code area_covered} counts (a picocli mixin of record-tool.sh and learning-host.sh). */
public final class AreaCellOption {
    @Option(names = "--area-cell-m", paramLabel = "M", defaultValue = "" + RunMetrics.DEFAULT_AREA_CELL_M,
            description = "The side of area_covered's cells, m (default: ${DEFAULT-VALUE}).")
    private double metres;

    public double metres() {
        return metres;
    }

    /** What is wrong with it, or null. */
    public String problem() {
        return metres > 0 && !Double.isInfinite(metres) ? null : "--area-cell-m must be > 0, got " + metres;
    }
}
