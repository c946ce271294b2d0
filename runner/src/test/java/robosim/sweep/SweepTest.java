package robosim.sweep;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A sweep on this machine, end to end: each run its own process; rows, tables and plots; --resume; a failed run
 * is a row and the sweep goes on; a kept recording alone gives the row's metrics again.
 */
class SweepTest {
    @TempDir
    Path dir;

    /** Runs sweep.sh's main here with these arguments: its exit code and what it wrote on stderr. */
    private record Result(int code, String err) {
    }

    private static synchronized Result sweep(String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream was = System.err;
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            return new Result(SweepMain.commandLine().execute(args), err.toString(StandardCharsets.UTF_8));
        } finally {
            System.setErr(was);
        }
    }

    private Path spec(String world, String body) throws Exception {
        Path f = dir.resolve("spec.xml");
        Files.writeString(f, "<sweep world=\"" + world + "\" steps=\"300\"><seeds from=\"1\" to=\"2\"/>" + body
                + "</sweep>");
        return f;
    }

    @Test
    void rowsTablesPlotsResumeAndARecordingThatGivesTheRowAgain() throws Exception {
        Path spec = spec(SweepFileTest.WANDER.toString(), "<param name=\"speed\" values=\"300 900\"/><metrics>"
                + "<metric name=\"distance_m\"/><metric name=\"area_covered\"/><metric report=\"turns\"/>"
                + "<metric class=\"" + MeanFinalX.class.getName() + "\"/></metrics>");
        Path out = dir.resolve("out");
        Result first = sweep(spec.toString(), "--out", out.toString(), "--jobs", "2", "--keep-recordings");
        assertEquals(0, first.code(), first.err());
        List<String> runs = Files.readAllLines(out.resolve("runs.csv"));
        assertEquals("index,seed,repetition,speed,status,exit_code,steps,robots,messages,control_failed,distance_m,"
                + "area_covered,turns,mean_final_x_m,error,wall_s", runs.get(0));
        assertEquals(5, runs.size(), String.join("\n", runs));
        for (int i = 1; i < runs.size(); i++) {
            List<String> f = Csv.fields(runs.get(i));
            assertEquals(List.of(Integer.toString(i - 1), i % 2 == 1 ? "1" : "2", "1", i <= 2 ? "300" : "900", "ok", "0",
                    "300", "6"), f.subList(0, 8), runs.get(i));
            assertTrue(Double.parseDouble(f.get(10)) > 0 && Double.parseDouble(f.get(12)) >= 0, runs.get(i));
        }
        assertNotEquals(Csv.fields(runs.get(1)).get(10), Csv.fields(runs.get(3)).get(10), "speed changes the distance");
        assertNotEquals(Csv.fields(runs.get(1)).get(10), Csv.fields(runs.get(2)).get(10), "the seed changes the run");
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
        List<String> row = Csv.fields(runs.get(3));
        assertEquals(List.of(row.get(10), row.get(11), row.get(12), row.get(13)),
                again.values().stream().map(Csv::number).toList());

        // --resume with every row there runs nothing and leaves the tables as they were
        byte[] runsBefore = Files.readAllBytes(out.resolve("runs.csv"));
        byte[] summaryBefore = Files.readAllBytes(out.resolve("summary.csv"));
        Result resumed = sweep(spec.toString(), "--out", out.toString(), "--resume");
        assertEquals(0, resumed.code(), resumed.err());
        assertTrue(resumed.err().contains(", 0 to run,"), resumed.err());
        assertArrayEquals(runsBefore, Files.readAllBytes(out.resolve("runs.csv")));
        assertArrayEquals(summaryBefore, Files.readAllBytes(out.resolve("summary.csv")));

        // a missing row is run again, and the same run gives the same row (but its wall time)
        Files.delete(out.resolve("rows").resolve("run-000001.csv"));
        Result refill = sweep(spec.toString(), "--out", out.toString(), "--resume");
        assertEquals(0, refill.code(), refill.err());
        assertTrue(refill.err().contains(", 1 to run,"), refill.err());
        assertEquals(withoutWallTime(runs), withoutWallTime(Files.readAllLines(out.resolve("runs.csv"))));

        // without --resume a directory that holds rows is refused
        Result again2 = sweep(spec.toString(), "--out", out.toString());
        assertEquals(2, again2.code());
        assertTrue(again2.err().contains("holds this sweep's rows already; --resume"), again2.err());
    }

    static List<String> withoutWallTime(List<String> csv) {
        List<String> out = new ArrayList<>();
        for (String line : csv) {
            List<String> f = Csv.fields(line);
            out.add(String.join(",", f.subList(0, f.size() - 1)));
        }
        return out;
    }

    @Test
    void aFailedRunIsARowWithItsExitCodeAndReasonSaidOnceAndTheSweepGoesOn() throws Exception {
        Path out = dir.resolve("failed");
        // (Wander reads its parameter speed as a number: each robot's control code fails at once)
        Result r = sweep(spec(SweepFileTest.WANDER.toString(), "<param name=\"speed\" values=\"fast\"/>").toString(),
                "--out", out.toString());
        assertEquals(1, r.code(), r.err());
        List<String> runs = Files.readAllLines(out.resolve("runs.csv"));
        assertEquals(3, runs.size(), "both runs have rows: " + runs);
        String reason = "parameter speed is 'fast', not a number";
        for (String line : runs.subList(1, 3)) {
            List<String> f = Csv.fields(line);
            assertEquals(List.of("failed", "4"), f.subList(4, 6), line);
            assertTrue(f.get(f.size() - 2).contains(reason), line);
        }
        assertEquals(1, r.err().lines().filter(l -> l.contains(" failed: ") && l.contains(reason)).count(),
                "the reason said once: " + r.err());
        assertTrue(r.err().contains("2 of 2 runs have rows, 2 failed"), r.err());
        try (var plots = Files.list(out.resolve("plots"))) {
            assertEquals(List.of(), plots.toList(), "no plot of a metric without a value of a run that succeeded");
        }
    }

    @Test
    void aFinishedSweepGrowsByMoreSeedsAndValuesRunningOnlyTheNewRuns() throws Exception {
        Path spec = dir.resolve("grows.xml");
        String head = "<sweep world=\"" + SweepFileTest.WANDER + "\" steps=\"100\">";
        Files.writeString(spec, head + "<seeds from=\"1\" to=\"2\"/><param name=\"speed\" values=\"300 900\"/></sweep>");
        Path out = dir.resolve("grows");
        Result first = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1");
        assertEquals(0, first.code(), first.err());
        String seed2speed900 = Files.readAllLines(out.resolve("runs.csv")).get(4); // (run 3: speed 900, seed 2)

        Files.writeString(spec, head + "<seeds from=\"1\" to=\"3\"/><param name=\"speed\" values=\"300 600 900\"/>"
                + "</sweep>");
        Result refused = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1");
        assertEquals(2, refused.code(), refused.err());
        assertTrue(refused.err().contains("--resume grows it"), refused.err());
        Files.createDirectories(out.resolve(".growing").resolve("rows")); // (a growth killed before its stage was whole)
        Result grown = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1", "--resume");
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
        Result steps = sweep(spec.toString(), "--out", out.toString(), "--resume");
        assertEquals(2, steps.code(), steps.err());
        assertTrue(steps.err().contains("its world, steps, layout"), steps.err());
    }

    @Test
    void whenTheFirstRunsAllFailAlikeTheSweepStopsSaysWhyAndRemovesTheirRows() throws Exception {
        Path spec = dir.resolve("doomed.xml");
        Files.writeString(spec, "<sweep world=\"" + SweepFileTest.WANDER + "\" steps=\"50\"><seeds from=\"1\" "
                + "to=\"8\"/><param name=\"speed\" values=\"fast\"/></sweep>");
        Path out = dir.resolve("doomed");
        Result r = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1");
        assertEquals(1, r.code(), r.err());
        assertTrue(r.err().contains("the first 3 runs all failed: ") && r.err().contains("parameter speed is 'fast'"),
                r.err());
        assertTrue(r.err().contains("0 of 8 runs have rows"), r.err());
    }

    @Test
    void aReportNoRobotMadeWarnsAndFailsTheSweepAndOverTakesTheRobotsValuesAsAsked() throws Exception {
        Path spec = spec(SweepFileTest.WANDER.toString(), "<metrics><metric report=\"turns\"/><metric report=\"turns\" "
                + "over=\"mean\"/><metric report=\"turns\" over=\"max\"/><metric report=\"turns\" over=\"each\"/>"
                + "<metric report=\"turnz\"/></metrics>");
        Path out = dir.resolve("over");
        Result r = sweep(spec.toString(), "--out", out.toString());
        assertEquals(1, r.code(), r.err());
        assertTrue(r.err().contains("no robot reported 'turnz' (reported: turns)"), r.err());
        assertTrue(r.err().contains("no robot reported 'turnz' in any run"), r.err());
        List<String> runs = Files.readAllLines(out.resolve("runs.csv"));
        List<String> header = Csv.fields(runs.get(0));
        for (String line : runs.subList(1, runs.size())) {
            List<String> f = Csv.fields(line);
            List<Double> each = new ArrayList<>();
            for (int c = 0; c < header.size(); c++) {
                if (header.get(c).matches("turns\\.w[0-9]") && !f.get(c).isEmpty()) {
                    each.add(Double.parseDouble(f.get(c)));
                }
            }
            assertTrue(!each.isEmpty(), line);
            double sum = each.stream().mapToDouble(Double::doubleValue).sum();
            assertEquals(sum, Double.parseDouble(f.get(header.indexOf("turns"))), 1e-9, line);
            assertEquals(sum / each.size(), Double.parseDouble(f.get(header.indexOf("turns.robot_mean"))), 1e-9, line);
            assertEquals(each.stream().mapToDouble(Double::doubleValue).max().orElseThrow(),
                    Double.parseDouble(f.get(header.indexOf("turns.robot_max"))), 1e-9, line);
        }
        assertTrue(!header.contains("turnz"), "no column for a report no robot made");
    }

    @Test
    void warmWorkersGiveTheRowsFreshJvmsGiveButTheWallTime() throws Exception {
        Path spec = spec(SweepFileTest.WANDER.toString(), "");
        Path warm = dir.resolve("warm");
        Path fresh = dir.resolve("fresh");
        Result w = sweep(spec.toString(), "--out", warm.toString(), "--jobs", "1");
        assertEquals(0, w.code(), w.err());
        Result f = sweep(spec.toString(), "--out", fresh.toString(), "--jobs", "1", "--fresh-jvm-per-run");
        assertEquals(0, f.code(), f.err());
        List<String> warmRows = Files.readAllLines(warm.resolve("runs.csv"));
        assertEquals(3, warmRows.size(), String.join("\n", warmRows));
        assertEquals(withoutWallTime(Files.readAllLines(fresh.resolve("runs.csv"))), withoutWallTime(warmRows));
    }

    @Test
    void aRunThatBreaksItsWarmWorkerIsOneFailedRowAndTheNextRunGetsAFreshWorker() throws Exception {
        Path world = dir.resolve("breaks.xml");
        Files.writeString(world, """
                <environment name="breaks" timeStepMs="100">
                  <arena width="4" height="2"/>
                  <param name="mode" value="stand"/>
                  <robots>
                    <robot name="b1" type="ArRobot" control="robosim.runner.BreaksItsJvm" x="1" y="1"/>
                  </robots>
                </environment>
                """);
        Path spec = dir.resolve("breaks-sweep.xml");
        Files.writeString(spec, "<sweep world=\"" + world + "\" steps=\"20\"><param name=\"mode\" "
                + "values=\"stand exit leave still\"/><seeds from=\"1\" to=\"1\"/></sweep>");
        Path out = dir.resolve("breaks");
        Result r = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1");
        assertEquals(1, r.code(), r.err());
        List<String> runs = Files.readAllLines(out.resolve("runs.csv"));
        assertEquals(5, runs.size(), String.join("\n", runs));
        List<String> stand = Csv.fields(runs.get(1));
        assertEquals(List.of("stand", "ok", "0"), stand.subList(3, 6), runs.get(1));
        List<String> exit = Csv.fields(runs.get(2));
        assertEquals(List.of("exit", "failed", "7"), exit.subList(3, 6), runs.get(2));
        assertTrue(exit.get(exit.size() - 2).contains("its warm JVM exited with code 7 during the run"), runs.get(2));
        List<String> leave = Csv.fields(runs.get(3));
        assertEquals(List.of("leave", "failed"), leave.subList(3, 5), runs.get(3));
        // (its control code ends as the run does; on a loaded machine it may still be ending when it is looked at)
        String why = leave.get(leave.size() - 2);
        assertTrue(why.contains("the run left threads running 5 s after its end: never-ends")
                || why.contains("the control code of b1 was still running after the run's end"), runs.get(3));
        assertEquals(Csv.fields(runs.get(1)).subList(4, 10), Csv.fields(runs.get(4)).subList(4, 10),
                "the run after them, in a fresh worker, is the first's again (its mode stands still too)");
        assertTrue(r.err().contains("4 of 4 runs have rows, 2 failed"), r.err());
    }
}
