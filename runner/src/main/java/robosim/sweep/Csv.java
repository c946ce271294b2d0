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

    /**
     * A statistic of runs as the summary writes it: to {@code decimals} places (half even), no trailing zeros; a
     * negative {@code decimals} means 12 significant digits (what a double's sum of a few terms holds: 0.44, not
     * 0.44000000000000006).
     */
    public static String number(double v, int decimals) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            return number(v);
        }
        java.math.BigDecimal d = new java.math.BigDecimal(v);
        d = decimals < 0 ? d.round(new java.math.MathContext(12, java.math.RoundingMode.HALF_EVEN))
                : d.setScale(decimals, java.math.RoundingMode.HALF_EVEN);
        d = d.stripTrailingZeros();
        String text = d.signum() == 0 ? "0" : d.toPlainString();
        return text.equals("-0") ? "0" : text;
    }

    /**
     * The places a mean, its interval and its standard deviation {@code sd} are written to: the sd's second
     * significant digit (an sd of 1.58 gives 1 place, 0.0012 gives 4, 158 gives none); -1 (12 significant digits)
     * where there is no spread to go by.
     */
    public static int places(double sd) {
        if (!(sd > 0) || Double.isInfinite(sd)) {
            return -1;
        }
        return (int) Math.max(0, Math.min(15, 1 - Math.floor(Math.log10(sd))));
    }
}
