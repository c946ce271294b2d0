package robosim.sweep;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The summary's intervals: a count's and a share's stay within their range, every other metric's is Student's t. */
class TablesTest {
    private static Row row(int index, double contacts, double area, double distance) {
        Map<String, String> v = new LinkedHashMap<>();
        v.put("index", Integer.toString(index));
        v.put("seed", Integer.toString(index + 1));
        v.put("repetition", "1");
        v.put("status", Row.OK);
        v.put("exit_code", "0");
        v.put("contacts", Double.toString(contacts));
        v.put("area_covered", Double.toString(area));
        v.put("distance_m", Double.toString(distance));
        return new Row(v);
    }

    @Test
    void aCountsAndASharesIntervalsStayInTheirRangeAndAreTheSameEveryTime() {
        Sweep sweep = new Sweep(Path.of("/s.xml"), Path.of("/w.xml"), 10, 1, 5, 1, Map.of(), Sweep.Layout.ONE_JVM, 0,
                List.of(), List.of(), 0.5);
        double[] contacts = {0, 0, 1, 0, 0};
        double[] area = {0.98, 1, 1, 0.99, 1};
        double[] distance = {10, 12, 11, 13, 9};
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            rows.add(row(i, contacts[i], area[i], distance[i]));
        }
        Tables tables = new Tables(sweep, rows);
        double[] c = tables.interval(Map.of(), "contacts");
        assertTrue(c[0] >= 0 && c[0] <= 0.2 && c[1] <= 1 && c[1] >= 0.2, c[0] + " to " + c[1]);
        double[] a = tables.interval(Map.of(), "area_covered");
        assertTrue(a[0] >= 0.98 && a[1] <= 1, a[0] + " to " + a[1]);
        assertArrayEquals(c, new Tables(sweep, rows).interval(Map.of(), "contacts"), "the same rows, the same interval");
        double[] d = tables.interval(Map.of(), "distance_m");
        // Student's t: mean 11, sd 1.58, t(0.975, 4) = 2.776
        assertEquals(11 - 2.776 * Math.sqrt(2.5) / Math.sqrt(5), d[0], 1e-3);
        assertEquals(11 + 2.776 * Math.sqrt(2.5) / Math.sqrt(5), d[1], 1e-3);
    }

    @Test
    void aReportDeclaredACountHasABootstrapIntervalNeverBelowZeroAndAnotherReportStudentsT() {
        List<MetricChoice> metrics = List.of(new MetricChoice(MetricChoice.Kind.REPORT, "found", null, true),
                new MetricChoice(MetricChoice.Kind.REPORT, "turns"));
        Sweep sweep = new Sweep(Path.of("/s.xml"), Path.of("/w.xml"), 10, 1, 5, 1, Map.of(), Sweep.Layout.ONE_JVM, 0,
                List.of(), metrics, 0.5);
        double[] found = {0, 0, 3, 0, 0};
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            Row r = row(i, 0, 1, 1);
            Map<String, String> v = new LinkedHashMap<>(r.values());
            v.put("found", Double.toString(found[i]));
            v.put("turns", Double.toString(found[i]));
            rows.add(new Row(v));
        }
        Tables tables = new Tables(sweep, rows);
        double[] count = tables.interval(Map.of(), "found");
        assertTrue(count[0] >= 0 && count[1] <= 3, count[0] + " to " + count[1]);
        double[] t = tables.interval(Map.of(), "turns");
        assertTrue(t[0] < 0, "Student's t of the same values reaches below zero: " + t[0]);
    }

    @Test
    void aSummaryIsWrittenToThePlacesItsSpreadSupports() {
        assertEquals(1, Csv.places(1.58));
        assertEquals(4, Csv.places(0.0012));
        assertEquals(0, Csv.places(158));
        assertEquals(-1, Csv.places(0));
        assertEquals("11", Csv.number(11.0000001, 1));
        assertEquals("1.6", Csv.number(1.58, 1));
        assertEquals("0.44", Csv.number(0.1 + 0.34, -1), "a sum's float noise gone");
        assertEquals("-2.5", Csv.number(-2.45, 1), "half even");
        assertEquals("0", Csv.number(-0.01, 1));
        Sweep sweep = new Sweep(Path.of("/s.xml"), Path.of("/w.xml"), 10, 1, 5, 1, Map.of(), Sweep.Layout.ONE_JVM, 0,
                List.of(), List.of(), 0.5);
        double[] distance = {10, 12, 11, 13, 9};
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            rows.add(row(i, 0, 1, distance[i]));
        }
        String text = new Tables(sweep, rows).text();
        assertTrue(text.startsWith("mean and 95% interval over the runs that succeeded:\nevery run (5 runs)\n"), text);
        assertTrue(text.contains("\n  distance_m    11  (9 to 13)\n"), text);
    }
}
