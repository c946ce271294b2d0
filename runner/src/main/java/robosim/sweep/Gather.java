package robosim.sweep;

import java.io.IOException;
import java.util.List;

/** Makes a sweep's tables and plots from the rows its directory holds (the local pool's end, Slurm's gather job). */
final class Gather {
    private Gather() {
    }

    /** Writes runs.csv, summary.csv and the plots; returns how many rows there were. */
    static int tables(Sweep sweep, OutputDirectory out) throws IOException {
        List<Row> rows = out.rowsWritten();
        Tables tables = new Tables(sweep, rows);
        tables.write(out.path());
        Plots.write(sweep, tables, rows, out.path());
        return rows.size();
    }

    /**
     * Writes runs.csv and summary.csv only (while the JVM stops: the plots' AWT cannot start then); returns how many
     * rows there were.
     */
    static int tablesWithoutPlots(Sweep sweep, OutputDirectory out) throws IOException {
        List<Row> rows = out.rowsWritten();
        new Tables(sweep, rows).write(out.path());
        return rows.size();
    }
}
