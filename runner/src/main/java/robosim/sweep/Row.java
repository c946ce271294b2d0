package robosim.sweep;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One run's row: column name to value, in column order. Kept as a file of its own in the output directory
 * ({@code rows/run-000017.csv}: a header line and a value line), written whole or not at all (a temporary file
 * renamed into place), so a run killed at any moment leaves no half row and {@code --resume} knows what is done.
 */
record Row(Map<String, String> values) {
    /** The columns every row starts with, before the parameters. */
    static final List<String> FIRST = List.of("index", "seed", "repetition");
    /** The columns after the parameters, from the run's exit and its summary line. */
    static final List<String> RUN = List.of("status", "exit_code", "steps", "robots", "messages", "control_failed");
    /** The columns every row ends with: the last error line of a failed run, and the run's wall time, s. */
    static final List<String> LAST = List.of("error", "wall_s");
    /** {@code status} of a run that exited 0 and whose metrics were read. */
    static final String OK = "ok";
    static final String FAILED = "failed";

    Row {
        values = Collections.unmodifiableMap(new LinkedHashMap<>(values));
    }

    /** The file of run {@code index}'s row in {@code rows}. */
    static Path file(Path rows, int index) {
        return rows.resolve(String.format("run-%06d.csv", index));
    }

    int index() {
        return Integer.parseInt(values.get("index"));
    }

    boolean ok() {
        return OK.equals(values.get("status"));
    }

    /** Writes this row into {@code file} at once (a temporary file beside it, renamed over it). */
    void write(Path file) throws IOException {
        Path temporary = file.resolveSibling("." + file.getFileName() + ".tmp-" + ProcessHandle.current().pid());
        String text = Csv.line(new ArrayList<>(values.keySet())) + Csv.line(new ArrayList<>(values.values()));
        Files.writeString(temporary, text, StandardCharsets.UTF_8);
        Files.move(temporary, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
    }

    /** The row in {@code file}; an IOException naming it when it is not a row. */
    static Row read(Path file) throws IOException {
        List<List<String>> lines;
        try {
            lines = Csv.rows(Files.readString(file, StandardCharsets.UTF_8));
        } catch (java.nio.charset.CharacterCodingException e) {
            throw new IOException(file + ": not a run's row (bytes that are not UTF-8)");
        } catch (com.fasterxml.jackson.core.JacksonException e) {
            lines = List.of();
        }
        List<String> names = lines.size() == 2 ? lines.get(0) : null;
        List<String> fields = lines.size() == 2 ? lines.get(1) : null;
        if (names == null || fields == null || names.size() != fields.size() || !names.containsAll(FIRST)) {
            throw new IOException(file + ": not a run's row (a header line and a value line)");
        }
        Map<String, String> values = new LinkedHashMap<>();
        for (int i = 0; i < names.size(); i++) {
            values.put(names.get(i), fields.get(i));
        }
        if (!List.of(OK, FAILED).contains(values.getOrDefault("status", "")) || !values.getOrDefault("exit_code", "")
                .matches("-?[0-9]{1,9}")) {
            throw new IOException(file + ": not a run's row (status '" + robosim.protocol.Printable.of(values.get("status"),
                    20) + "', exit_code '" + robosim.protocol.Printable.of(values.get("exit_code"), 20) + "')");
        }
        String index = values.get("index");
        if (!index.matches("[0-9]{1,9}") || !file.getFileName().equals(file(file.getParent(), Integer.parseInt(index))
                .getFileName())) {
            throw new IOException(file + ": index '" + robosim.protocol.Printable.of(index, 20) + "' is not this row "
                    + "file's run");
        }
        return new Row(values);
    }
}
