package robosim.sweep;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.sweep.SweepCommand.spec;
import static robosim.sweep.SweepCommand.sweep;
import static robosim.sweep.SweepCommand.withoutWallTime;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A sweep on this machine, end to end: warm workers, rows, tables and plots; --resume, and a sweep grown by it; a
 * kept recording alone gives the row's metrics again; warm runs give fresh runs' rows.
 */
class SweepTest {
    @TempDir
    Path dir;


    @Test
    void rowsTablesPlotsResumeAndARecordingThatGivesTheRowAgain() throws Exception {
        Path spec = spec(dir, SweepFileTest.WANDER.toString(), "<param name=\"speed\" values=\"300 900\"/><metrics>"
                + "<metric name=\"distance_m\"/><metric name=\"area_covered\"/><metric report=\"turns\"/>"
                + "<metric class=\"" + MeanFinalX.class.getName() + "\"/></metrics>");
        Path out = dir.resolve("out");
        SweepCommand first = sweep(spec.toString(), "--out", out.toString(), "--jobs", "2", "--keep-recordings");
        assertEquals(0, first.code(), first.err());
        List<String> runs = Files.readAllLines(out.resolve("runs.csv"));
        assertEquals("index,seed,repetition,speed,status,exit_code,steps,robots,messages,control_failed,distance_m,"
                + "area_covered,turns,mean_final_x_m,error,wall_s", runs.get(0));
        assertEquals(5, runs.size(), String.join("\n", runs));
        for (int i = 1; i < runs.size(); i++) {
            List<String> f = SweepCommand.fields(runs.get(i));
            assertEquals(List.of(Integer.toString(i - 1), i % 2 == 1 ? "1" : "2", "1", i <= 2 ? "300" : "900", "ok", "0",
                    "300", "6"), f.subList(0, 8), runs.get(i));
            assertTrue(Double.parseDouble(f.get(10)) > 0 && Double.parseDouble(f.get(12)) >= 0, runs.get(i));
        }
        assertNotEquals(SweepCommand.fields(runs.get(1)).get(10), SweepCommand.fields(runs.get(3)).get(10), "speed changes the distance");
        assertNotEquals(SweepCommand.fields(runs.get(1)).get(10), SweepCommand.fields(runs.get(2)).get(10), "the seed changes the run");
        List<String> summary = Files.readAllLines(out.resolve("summary.csv"));
        assertEquals(3, summary.size());
        assertTrue(summary.get(0).startsWith("speed,runs,failed,distance_m_mean,distance_m_sd,distance_m_ci95_low,"
                + "distance_m_ci95_high,"), summary.get(0));
        assertTrue(summary.get(1).startsWith("300,2,0,"), summary.get(1));
        for (String metric : List.of("distance_m", "area_covered", "turns", "mean_final_x_m")) {
            byte[] png = Files.readAllBytes(out.resolve("plots").resolve(metric + "-vs-speed.png"));
            assertArrayEquals(new byte[] {(byte) 0x89, 'P', 'N', 'G'}, java.util.Arrays.copyOf(png, 4), metric);
        }

        // a recording alone gives the row's metrics again
        Path recording = out.resolve("recordings").resolve("run-000002.rec");
        Map<String, Double> again = RunMetrics.of(recording, SweepFile.read(spec).metrics(),
                RunMetrics.DEFAULT_AREA_CELL_M);
        List<String> row = SweepCommand.fields(runs.get(3));
        assertEquals(List.of(row.get(10), row.get(11), row.get(12), row.get(13)),
                again.values().stream().map(Csv::number).toList());

        // --resume with every row there runs nothing and leaves the tables as they were
        byte[] runsBefore = Files.readAllBytes(out.resolve("runs.csv"));
        byte[] summaryBefore = Files.readAllBytes(out.resolve("summary.csv"));
        SweepCommand resumed = sweep(spec.toString(), "--out", out.toString(), "--resume");
        assertEquals(0, resumed.code(), resumed.err());
        assertTrue(resumed.err().contains(", 0 to run,"), resumed.err());
        assertArrayEquals(runsBefore, Files.readAllBytes(out.resolve("runs.csv")));
        assertArrayEquals(summaryBefore, Files.readAllBytes(out.resolve("summary.csv")));

        // a missing row is run again, and the same run gives the same row (but its wall time)
        Files.delete(out.resolve("rows").resolve("run-000001.csv"));
        SweepCommand refill = sweep(spec.toString(), "--out", out.toString(), "--resume");
        assertEquals(0, refill.code(), refill.err());
        assertTrue(refill.err().contains(", 1 to run,"), refill.err());
        assertEquals(withoutWallTime(runs), withoutWallTime(Files.readAllLines(out.resolve("runs.csv"))));

        // without --resume a directory that holds rows is refused
        SweepCommand again2 = sweep(spec.toString(), "--out", out.toString());
        assertEquals(2, again2.code());
        assertTrue(again2.err().contains("holds this sweep's rows already; --resume"), again2.err());
    }


    @Test
    void aFinishedSweepGrowsByMoreSeedsAndValuesRunningOnlyTheNewRuns() throws Exception {
        Path spec = dir.resolve("grows.xml");
        String head = "<sweep world=\"" + SweepFileTest.WANDER + "\" steps=\"100\">";
        Files.writeString(spec, head + "<seeds from=\"1\" to=\"2\"/><param name=\"speed\" values=\"300 900\"/></sweep>");
        Path out = dir.resolve("grows");
        SweepCommand first = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1");
        assertEquals(0, first.code(), first.err());
        String seed2speed900 = Files.readAllLines(out.resolve("runs.csv")).get(4); // (run 3: speed 900, seed 2)

        Files.writeString(spec, head + "<seeds from=\"1\" to=\"3\"/><param name=\"speed\" values=\"300 600 900\"/>"
                + "</sweep>");
        SweepCommand refused = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1");
        assertEquals(2, refused.code(), refused.err());
        assertTrue(refused.err().contains("--resume grows it"), refused.err());
        Files.createDirectories(out.resolve(".growing").resolve("rows")); // (a growth killed before its stage was whole)
        SweepCommand grown = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1", "--resume");
        assertEquals(0, grown.code(), grown.err());
        assertTrue(grown.err().contains("cut short before its rows were renumbered; its stage removed"), grown.err());
        assertTrue(grown.err().contains("9 runs (3 combinations x 3 seeds, 100 steps, one-jvm), 5 to run"), grown.err());
        List<String> rows = Files.readAllLines(out.resolve("runs.csv"));
        assertEquals(10, rows.size(), String.join("\n", rows));
        assertEquals(withoutWallTime(List.of(seed2speed900.replaceFirst("^3,", "7,"))),
                withoutWallTime(List.of(rows.get(8))), "run 3 of the first file is run 7 of the grown one, kept");

        Path fresh = dir.resolve("fresh");
        assertEquals(0, sweep(spec.toString(), "--out", fresh.toString(), "--jobs", "1").code());
        assertEquals(withoutWallTime(Files.readAllLines(fresh.resolve("runs.csv"))), withoutWallTime(rows),
                "the grown sweep's rows are the bigger file's");

        Files.writeString(spec, head.replace("100", "200") + "<seeds from=\"1\" to=\"4\"/><param name=\"speed\" "
                + "values=\"300 600 900\"/></sweep>");
        SweepCommand steps = sweep(spec.toString(), "--out", out.toString(), "--resume");
        assertEquals(2, steps.code(), steps.err());
        assertTrue(steps.err().contains("its world, steps, layout"), steps.err());
    }

    @Test
    void warmWorkersGiveTheRowsFreshJvmsGiveButTheWallTime() throws Exception {
        Path spec = spec(dir, SweepFileTest.WANDER.toString(), "");
        Path warm = dir.resolve("warm");
        Path fresh = dir.resolve("fresh");
        SweepCommand w = sweep(spec.toString(), "--out", warm.toString(), "--jobs", "1");
        assertEquals(0, w.code(), w.err());
        SweepCommand f = sweep(spec.toString(), "--out", fresh.toString(), "--jobs", "1", "--fresh-jvm-per-run");
        assertEquals(0, f.code(), f.err());
        List<String> warmRows = Files.readAllLines(warm.resolve("runs.csv"));
        assertEquals(3, warmRows.size(), String.join("\n", warmRows));
        assertEquals(withoutWallTime(Files.readAllLines(fresh.resolve("runs.csv"))), withoutWallTime(warmRows));
    }

}
