package robosim.sweep;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.Comparator;
import java.util.List;

/**
 * A sweep's output directory: {@code sweep.xml} (the sweep file it was made by, copied) and {@code origin} (where
 * that file is, so a Slurm task reads the same), {@code rows/} (one file per finished run), {@code logs/} (each
 * run's output), {@code recordings/} (with {@code --keep-recordings}), and the tables and plots made from the rows:
 * {@code runs.csv}, {@code summary.csv}, {@code plots/}. On a cluster it must be on the file system every node
 * shares.
 */
final class OutputDirectory {
    private final Path dir;

    OutputDirectory(Path dir) {
        this.dir = dir.toAbsolutePath().normalize();
    }

    Path path() {
        return dir;
    }

    Path rows() {
        return dir.resolve("rows");
    }

    Path row(int index) {
        return Row.file(rows(), index);
    }

    Path log(int index) {
        return dir.resolve("logs").resolve(String.format("run-%06d.log", index));
    }

    Path recording(int index) {
        return dir.resolve("recordings").resolve(String.format("run-%06d.rec", index));
    }

    Path slurm() {
        return dir.resolve("slurm");
    }

    /**
     * Makes the directory for {@code sweep}, or, with {@code resume}, checks it was made by the same sweep file;
     * refuses one that holds another sweep, or this one's rows without {@code resume}.
     */
    void prepare(Sweep sweep, boolean resume) throws SweepException, IOException {
        Path copy = dir.resolve("sweep.xml");
        byte[] spec = Files.readAllBytes(sweep.file());
        if (Files.exists(copy)) {
            if (!Arrays.equals(Files.readAllBytes(copy), spec)) {
                throw new SweepException(dir + ": holds the rows of another sweep file (its sweep.xml differs from "
                        + sweep.file() + "); give another --out");
            }
            if (!resume && hasRows()) {
                throw new SweepException(dir + ": holds this sweep's rows already; --resume runs only what is missing "
                        + "(or give another --out)");
            }
        } else if (Files.isDirectory(dir) && !isEmpty(dir)) {
            throw new SweepException(dir + ": not empty and not a sweep's output directory; give a new or empty --out");
        } else if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new SweepException(dir + ": not a directory");
        }
        for (Path d : List.of(dir, rows(), dir.resolve("logs"), dir.resolve("recordings"))) {
            Files.createDirectories(d);
        }
        if (!Files.exists(copy)) {
            Files.write(copy, spec);
            Files.writeString(dir.resolve("origin"), sweep.file() + "\n", StandardCharsets.UTF_8);
        }
    }

    /**
     * The sweep this directory was made by, read from its origin, which must still be what was copied (a task
     * reads it long after the submission).
     */
    Sweep sweep() throws SweepException, IOException {
        Path origin = dir.resolve("origin");
        if (!Files.exists(origin)) {
            throw new SweepException(dir + ": not a sweep's output directory (no origin file)");
        }
        Path file = Path.of(Files.readString(origin, StandardCharsets.UTF_8).strip());
        if (!Files.exists(file) || !Arrays.equals(Files.readAllBytes(file), Files.readAllBytes(dir.resolve("sweep.xml")))) {
            throw new SweepException(file + ": changed or gone since " + dir + " was made from it");
        }
        return SweepFile.read(file);
    }

    private boolean hasRows() throws IOException {
        return Files.isDirectory(rows()) && !isEmpty(rows());
    }

    private static boolean isEmpty(Path d) throws IOException {
        try (DirectoryStream<Path> s = Files.newDirectoryStream(d)) {
            return !s.iterator().hasNext();
        }
    }

    /** The runs of {@code sweep} that have no row yet, in order. */
    List<Integer> missing(Sweep sweep) throws IOException {
        BitSet done = new BitSet();
        for (Row r : rowsWritten()) {
            done.set(r.index());
        }
        List<Integer> out = new ArrayList<>();
        for (int i = 0; i < sweep.runs(); i++) {
            if (!done.get(i)) {
                out.add(i);
            }
        }
        return out;
    }

    /** Every row written so far, by index (a temporary file of a run still writing is not one). */
    List<Row> rowsWritten() throws IOException {
        List<Row> rows = new ArrayList<>();
        if (!Files.isDirectory(rows())) {
            return rows;
        }
        try (DirectoryStream<Path> s = Files.newDirectoryStream(rows(), "run-*.csv")) {
            for (Path p : s) {
                rows.add(Row.read(p));
            }
        }
        rows.sort(Comparator.comparingInt(Row::index));
        return rows;
    }
}
