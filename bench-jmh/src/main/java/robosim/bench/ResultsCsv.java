package robosim.bench;

import com.fasterxml.jackson.databind.MappingIterator;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvSchema;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A benchmark's results file (results.csv, speed.csv: a header line, then a row a run), each row by its columns'
 * names, and the newest sitting's rows.
 */
final class ResultsCsv {
    private ResultsCsv() {
    }

    /** The rows of {@code file} (a column a row lacks is absent from its map). */
    static List<Map<String, String>> read(Path file) throws IOException {
        List<Map<String, String>> rows = new ArrayList<>();
        try (MappingIterator<Map<String, String>> it = new CsvMapper().readerForMapOf(String.class)
                .with(CsvSchema.emptySchema().withHeader())
                .readValues(Files.readString(file, StandardCharsets.UTF_8))) {
            while (it.hasNextValue()) {
                rows.add(it.nextValue());
            }
        }
        return rows;
    }

    /** The rows of the newest sitting (the greatest {@code sitting}) that have a {@code needed} value. */
    static List<Map<String, String>> newest(List<Map<String, String>> rows, String needed) {
        String newest = "";
        for (Map<String, String> r : rows) {
            String s = r.getOrDefault("sitting", "");
            newest = s.compareTo(newest) > 0 ? s : newest;
        }
        List<Map<String, String>> out = new ArrayList<>();
        for (Map<String, String> r : rows) {
            if (newest.equals(r.get("sitting")) && !r.getOrDefault(needed, "").isEmpty()) {
                out.add(r);
            }
        }
        return out;
    }
}
