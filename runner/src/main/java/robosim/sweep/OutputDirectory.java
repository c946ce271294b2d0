package robosim.sweep;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.Comparator;
import java.util.List;

/**
 * A sweep's output directory: {@code sweep.xml} and {@code world.xml} (the sweep file it was made by and its world,
 * copied: rows of another sweep or world never mix with these) and {@code origin} (where the sweep file is, so a
 * Slurm task reads the same), {@code rows/} (one file per finished run), {@code logs/} (each
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

    /** Where run {@code index}'s loop functions write their own files (made if the world has them). */
    Path outputs(int index) {
        return dir.resolve("outputs").resolve(String.format("run-%06d", index));
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
            settleGrowth();
            if (!Arrays.equals(Files.readAllBytes(dir.resolve("world.xml")), Files.readAllBytes(sweep.world()))) {
                throw new SweepException(dir + ": its rows are of another " + sweep.world().getFileName() + " (it changed "
                        + "since; world.xml there is the one they are of); give another --out");
            }
            byte[] earlier = Files.readAllBytes(copy);
            if (!Arrays.equals(earlier, spec)) {
                String why = SweepFile.readEarlier(sweep.file(), earlier).growthProblem(sweep);
                if (!resume || why != null) {
                    throw new SweepException(dir + ": holds the rows of another sweep file (its sweep.xml differs from "
                            + sweep.file() + (why == null ? "; --resume grows it: it only adds seeds, values or repetitions"
                            : ": " + why + "; --resume grows a sweep only by more seeds, values or repetitions")
                            + "); give another --out");
                }
                grow(SweepFile.readEarlier(sweep.file(), earlier), sweep, spec);
                return;
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
            Files.copy(sweep.world(), dir.resolve("world.xml"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            Files.writeString(dir.resolve("origin"), sweep.file() + "\n", StandardCharsets.UTF_8);
            Files.write(copy, spec); // (last: a directory with sweep.xml has the rest)
        }
    }

    /** Whether this is a sweep's output directory already (its sweep.xml is there). */
    boolean isSweep() {
        return Files.exists(dir.resolve("sweep.xml"));
    }

    /** Where a growth stages its renumbered rows, logs and recordings (there only while one is under way). */
    private static final String GROWING = ".growing";
    /** In the stage once it is whole: from then on the growth is finished (rolled forward), never undone. */
    private static final String SWAPPING = "swapping";
    private static final List<String> PARTS = List.of("rows", "logs", "recordings");

    /**
     * Makes this directory, whose rows are of {@code earlier}, {@code later}'s: every row mapped to its run's index in
     * {@code later} first (a run {@code later} does not have refuses the growth before anything is touched), then
     * each row, log and recording renumbered into a stage ({@link #GROWING}; logs copied, recordings linked or
     * copied, so the directory is as it was until the stage is whole), then the stage marked whole and swapped in
     * ({@link #finishGrowth}).
     */
    private void grow(Sweep earlier, Sweep later, byte[] spec) throws IOException, SweepException {
        List<Row> rows = rowsWritten();
        java.util.Map<Row, Integer> to = new java.util.LinkedHashMap<>();
        for (Row r : rows) {
            Sweep.Run run = earlier.run(r.index());
            long index = later.indexOf(run.parameters(), run.seed(), run.repetition());
            if (index < 0) {
                throw new SweepException(dir + ": run " + r.index() + " is no run of " + later.file() + "; give another --out");
            }
            to.put(r, (int) index);
        }
        Path stage = dir.resolve(GROWING);
        try {
            for (String part : PARTS) {
                Files.createDirectories(stage.resolve(part));
            }
            for (java.util.Map.Entry<Row, Integer> e : to.entrySet()) {
                int from = e.getKey().index();
                int index = e.getValue();
                java.util.Map<String, String> values = new java.util.LinkedHashMap<>(e.getKey().values());
                values.put("index", Integer.toString(index));
                new Row(values).write(Row.file(stage.resolve("rows"), index));
                if (Files.exists(log(from))) {
                    Files.copy(log(from), stage.resolve("logs").resolve(log(index).getFileName()));
                }
                if (Files.exists(recording(from))) {
                    Path staged = stage.resolve("recordings").resolve(recording(index).getFileName());
                    try {
                        Files.createLink(staged, recording(from));
                    } catch (IOException | UnsupportedOperationException noLink) {
                        Files.copy(recording(from), staged);
                    }
                }
            }
            Files.write(stage.resolve("sweep.xml"), spec);
            Files.writeString(stage.resolve("origin"), later.file() + "\n", StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            deleteTree(stage); // (nothing of the directory was touched: it stays the earlier sweep's)
            throw e;
        }
        Files.createFile(stage.resolve(SWAPPING));
        finishGrowth();
    }

    /**
     * Finishes a growth whose stage is whole, from wherever it stopped: each part not yet swapped in takes the place
     * of the earlier one, then origin and sweep.xml are the later sweep's, then the stage goes.
     */
    private void finishGrowth() throws IOException {
        Path stage = dir.resolve(GROWING);
        for (String part : PARTS) {
            if (Files.exists(stage.resolve(part))) {
                if (Files.exists(dir.resolve(part))) {
                    Files.move(dir.resolve(part), stage.resolve(part + ".earlier"));
                }
                Files.move(stage.resolve(part), dir.resolve(part));
            }
        }
        for (String file : List.of("origin", "sweep.xml")) { // (sweep.xml last: it says whose the rows are)
            if (Files.exists(stage.resolve(file))) {
                Files.move(stage.resolve(file), dir.resolve(file), StandardCopyOption.ATOMIC_MOVE,
                        StandardCopyOption.REPLACE_EXISTING);
            }
        }
        deleteTree(stage);
    }

    /**
     * A growth cut short (this JVM killed during it): finished when its stage was whole, else its stage removed (the
     * directory untouched); says which on stderr.
     */
    private void settleGrowth() throws IOException {
        Path stage = dir.resolve(GROWING);
        if (!Files.exists(stage)) {
            return;
        }
        if (Files.exists(stage.resolve(SWAPPING))) {
            finishGrowth();
            System.err.println("sweep: " + dir + ": a growth of its sweep was cut short after its rows were renumbered; "
                    + "finished now");
        } else {
            deleteTree(stage);
            System.err.println("sweep: " + dir + ": a growth of its sweep was cut short before its rows were "
                    + "renumbered; its stage removed, the rows as they were");
        }
    }

    private static void deleteTree(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        try (var all = Files.walk(root)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
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
        Sweep sweep = SweepFile.readAgain(file);
        if (!Arrays.equals(Files.readAllBytes(sweep.world()), Files.readAllBytes(dir.resolve("world.xml")))) {
            throw new SweepException(sweep.world() + ": changed since " + dir + " was made from it");
        }
        return sweep;
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
            done.set(r.index()); // (an index beyond the sweep's is ignored: it is no run of it)
        }
        List<Integer> out = new ArrayList<>();
        for (int i = 0; i < sweep.runs(); i++) {
            if (!done.get(i)) {
                out.add(i);
            }
        }
        return out;
    }

    /**
     * Every row written so far, by index (a temporary file of a run still writing is not one). A file that is not a
     * row (damaged by hand) is left out, said once on stderr: delete it and {@code --resume} runs its run again.
     */
    List<Row> rowsWritten() throws IOException {
        List<Row> rows = new ArrayList<>();
        if (!Files.isDirectory(rows())) {
            return rows;
        }
        try (DirectoryStream<Path> s = Files.newDirectoryStream(rows(), "run-*.csv")) {
            for (Path p : s) {
                try {
                    rows.add(Row.read(p));
                } catch (IOException | RuntimeException e) {
                    if (unreadable.add(p)) {
                        System.err.println("sweep: " + e.getMessage() + "; left out (delete it and --resume runs it "
                                + "again)");
                    }
                }
            }
        }
        rows.sort(Comparator.comparingInt(Row::index));
        return rows;
    }

    /** Row files found not to be rows, said once each. */
    private final java.util.Set<Path> unreadable = java.util.concurrent.ConcurrentHashMap.newKeySet();

    /**
     * Holds this directory for one sweep on this machine until the lock is closed or this JVM ends ({@code .lock}):
     * a second sweep started on it is refused rather than writing the same rows.
     */
    java.io.Closeable lock() throws SweepException, IOException {
        java.nio.channels.FileChannel channel = java.nio.channels.FileChannel.open(dir.resolve(".lock"),
                java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.WRITE);
        java.nio.channels.FileLock lock;
        try {
            lock = channel.tryLock();
        } catch (java.nio.channels.OverlappingFileLockException e) {
            lock = null; // (held by this JVM: another sweep in it)
        }
        if (lock == null) {
            channel.close();
            throw new SweepException(dir + ": another sweep is running in it");
        }
        return channel; // (closing it releases the lock)
    }
}
