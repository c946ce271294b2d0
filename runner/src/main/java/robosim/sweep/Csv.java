package robosim.sweep;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.MappingIterator;
import com.fasterxml.jackson.databind.ObjectReader;
import com.fasterxml.jackson.databind.ObjectWriter;
import com.fasterxml.jackson.dataformat.csv.CsvGenerator;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvParser;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * RoboSim's CSV, for every file of rows it writes or reads (a sweep's rows and tables, pose logs, record-tool's
 * tables): RFC 4180 through jackson-dataformat-csv (a field is quoted only when it holds a comma, a quote or a line
 * break; lines end in {@code \n}), and the numbers as the tables write them ({@link #number}).
 */
public final class Csv {
    private static final CsvMapper MAPPER = CsvMapper.builder()
            .enable(CsvGenerator.Feature.STRICT_CHECK_FOR_QUOTING) // (quoted only when it must be)
            .enable(CsvParser.Feature.WRAP_AS_ARRAY)
            .build();
    private static final ObjectWriter ROW = MAPPER.writer();
    private static final ObjectReader ROWS = MAPPER.readerForListOf(String.class);

    private Csv() {
    }

    /** One line of {@code fields} (null as empty), with its line break. */
    public static String line(List<String> fields) {
        try {
            return ROW.writeValueAsString(fields);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a list of texts is always a CSV line", e);
        }
    }

    /** Every row of {@code text} (the header too, if it has one); an IOException when it is not CSV (a quote left open). */
    public static List<List<String>> rows(String text) throws IOException {
        List<List<String>> out = new ArrayList<>();
        try (MappingIterator<List<String>> it = ROWS.readValues(text)) {
            while (it.hasNextValue()) {
                out.add(it.nextValue());
            }
        }
        return out;
    }

    /** A number as the tables write it: a whole number without a fraction, else the shortest decimal that reads back as the same double (Java's). */
    public static String number(double v) {
        if (Double.isNaN(v)) {
            return "";
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }
}
