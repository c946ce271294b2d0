package robosim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Sweep files: how a good one numbers its runs, and every bad one refused in one line before any run. */
class SweepFileTest {
    static final Path WANDER = Path.of("../test-envs/wander.xml").toAbsolutePath().normalize();

    @TempDir
    Path dir;

    private Path write(String xml) throws Exception {
        Path f = dir.resolve("sweep.xml");
        Files.writeString(f, xml);
        return f;
    }

    static String sweep(String attributes, String body) {
        return "<sweep world=\"" + WANDER + "\" steps=\"100\"" + attributes + ">" + body + "</sweep>";
    }

    @Test
    void runsAreNumberedCombinationsThenSeedsThenRepetitions() throws Exception {
        Sweep s = SweepFile.read(write(sweep(" repeat=\"2\"", "<seeds from=\"5\" to=\"6\"/>"
                + "<param name=\"speed\" values=\"200 400 600\"/>")));
        assertEquals(12, s.runs());
        assertEquals(new Sweep.Run(0, 5, 1, Map.of("speed", "200")), s.run(0));
        assertEquals(new Sweep.Run(1, 5, 2, Map.of("speed", "200")), s.run(1));
        assertEquals(new Sweep.Run(2, 6, 1, Map.of("speed", "200")), s.run(2));
        assertEquals(new Sweep.Run(4, 5, 1, Map.of("speed", "400")), s.run(4));
        assertEquals(new Sweep.Run(11, 6, 2, Map.of("speed", "600")), s.run(11));
        assertEquals(Sweep.Layout.ONE_JVM, s.layout());
        assertEquals(List.of(), s.metrics(), "none named: every built-in one and every report");
        assertEquals(Sweep.SHORT_RUNS, s.jvmOptions());
        assertEquals(List.of(), SweepFile.read(write(sweep(" jvm=\"\"", "<seeds from=\"1\" to=\"1\"/>"))).jvmOptions());
    }

    @Test
    void valuesAreSeparatedBySpacesOrCommasAndAReportIsTakenOverTheRobotsAsTheFileSays() throws Exception {
        Sweep s = SweepFile.read(write(sweep("", "<seeds from=\"1\" to=\"1\"/><param name=\"speed\" "
                + "values=\"200,400, 600 800\"/><metrics><metric report=\"turns\"/><metric report=\"turns\" "
                + "over=\"mean\"/><metric report=\"turns\" over=\"each\"/><metric report=\"turns\" over=\"max\" count=\"true\"/>"
                + "</metrics>")));
        assertEquals(List.of("200", "400", "600", "800"), s.values().get("speed"));
        assertEquals(List.of(new MetricChoice(MetricChoice.Kind.REPORT, "turns"),
                new MetricChoice(MetricChoice.Kind.REPORT, "turns", MetricChoice.Over.MEAN),
                new MetricChoice(MetricChoice.Kind.REPORT, "turns", MetricChoice.Over.EACH),
                new MetricChoice(MetricChoice.Kind.REPORT, "turns", MetricChoice.Over.MAX, true)), s.metrics());
        assertEquals("turns", s.metrics().get(0).column(null));
        assertEquals("turns.robot_mean", s.metrics().get(1).column(null));
        assertEquals("turns.w3", s.metrics().get(2).column("w3"));
        assertEquals(s.metrics().get(1), MetricChoice.parse("report:turns:mean"));
    }

    @Test
    void twoParametersMakeAGridTheFirstChangingSlowest() throws Exception {
        Path world = dir.resolve("world.xml");
        Files.writeString(world, Files.readString(WANDER).replace("x=\"1\" y=\"1\"", "x=\"${x:1}\" y=\"1\""));
        Sweep s = SweepFile.read(write("<sweep world=\"world.xml\" steps=\"10\"><seeds from=\"1\" to=\"1\"/>"
                + "<param name=\"speed\" values=\"1 2\"/><param name=\"x\" values=\"1 1.5 2\"/></sweep>"));
        assertEquals(List.of(Map.of("speed", "1", "x", "1"), Map.of("speed", "1", "x", "1.5"),
                Map.of("speed", "1", "x", "2"), Map.of("speed", "2", "x", "1"), Map.of("speed", "2", "x", "1.5"),
                Map.of("speed", "2", "x", "2")), s.combinations());
    }

    private String refused(String xml) throws Exception {
        Path f = write(xml);
        SweepException e = assertThrows(SweepException.class, () -> SweepFile.read(f));
        assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
        assertTrue(e.getMessage().startsWith(f.toString()), "names the file: " + e.getMessage());
        return e.getMessage();
    }

    @Test
    void everyBadFileIsOneLine() throws Exception {
        String seeds = "<seeds from=\"1\" to=\"3\"/>";
        assertTrue(refused(sweep(" stepz=\"4\"", seeds)).contains("unknown element or attribute 'stepz'"));
        assertTrue(refused(sweep("", seeds + "<parameter name=\"speed\"/>"))
                .contains("unknown element or attribute 'parameter'"));
        String unknown = refused(sweep("", seeds + "<param name=\"sped\" values=\"1 2\"/>"));
        assertTrue(unknown.contains("<param name=\"sped\">: not a parameter of ") && unknown.endsWith(
                "(the parameters a sweep may set there: speed)"), unknown);
        Path seeded = dir.resolve("seeded.xml");
        Files.writeString(seeded, Files.readString(WANDER).replaceFirst("seed=\"\\d+\"", "seed=\"\\${seed:1}\""));
        String notSeed = refused("<sweep world=\"seeded.xml\" steps=\"5\">" + seeds
                + "<param name=\"sped\" values=\"1\"/></sweep>");
        assertTrue(notSeed.endsWith("(the parameters a sweep may set there: speed)"), "seed is <seeds>: " + notSeed);
        assertTrue(refused(sweep("", "<seeds from=\"4\" to=\"3\"/>")).contains("is an empty range"));
        assertTrue(refused(sweep("", "")).contains("<seeds from=\"1\" to=\"10\"/> is needed"));
        assertTrue(refused(sweep("", seeds + "<param name=\"speed\" values=\"1 1\"/>")).contains("names a value twice"));
        assertTrue(refused(sweep(" layout=\"cloud\"", seeds)).contains("is not one of one-jvm, processes, one-process"));
        assertTrue(refused(sweep(" jvm=\"-Xmx1g -cp /x\"", seeds)).contains("'-cp' is not a JVM option this can take"));
        assertTrue(refused(sweep("", seeds + "<metrics><metric name=\"speediness\"/></metrics>"))
                .contains("'speediness' is not a built-in metric"));
        assertTrue(refused(sweep("", seeds + "<metrics><metric class=\"no.Such\"/></metrics>"))
                .contains("class no.Such is not a robosim.sweep.Metric"));
        assertTrue(refused("<sweep world=\"missing.xml\" steps=\"5\">" + seeds + "</sweep>").contains("missing.xml: file not found"));
        Path broken = dir.resolve("broken.xml");
        Files.writeString(broken, Files.readString(WANDER).replace("timeStepMs=\"100\"", "timeStepMs=\"-1\""));
        assertTrue(refused("<sweep world=\"broken.xml\" steps=\"5\">" + seeds + "</sweep>")
                .contains("timeStepMs must be > 0"));
        assertTrue(refused(sweep("", seeds + "<metrics><metric report=\"turns\" over=\"median\"/></metrics>"))
                .contains("over is one of sum, mean, min, max, each"));
        assertTrue(refused(sweep("", seeds + "<metrics><metric name=\"contacts\" over=\"mean\"/></metrics>"))
                .contains("over goes with report=\"NAME\""));
        assertTrue(refused(sweep("", seeds + "<metrics><metric name=\"contacts\" count=\"true\"/></metrics>"))
                .contains("count goes with report=\"NAME\""));
        assertTrue(refused(sweep("", seeds + "<metrics><metric report=\"turns\" count=\"yes\"/></metrics>"))
                .contains("count is true (a count: never below zero, a bootstrap interval) or false"));
        Path elsewhere = dir.resolve("elsewhere.xml");
        Files.writeString(elsewhere, Files.readString(WANDER).replace("robosim.examples.Wander", "my.Missing"));
        String missing = refused("<sweep world=\"elsewhere.xml\" steps=\"5\">" + seeds + "</sweep>");
        assertTrue(missing.contains("control class my.Missing is not on the class path (add its classes with "
                + "--classpath or ROBOSIM_CLASSPATH); no run was started"), missing);
        Path placed = dir.resolve("placed.xml");
        Files.writeString(placed, Files.readString(WANDER).replace("x=\"1\" y=\"1\"", "x=\"${x:1}\" y=\"1\""));
        assertTrue(refused("<sweep world=\"placed.xml\" steps=\"5\">" + seeds + "<param name=\"x\" values=\"1 99\"/></sweep>")
                .contains("does not fit inside the arena"), "every combination must load");
    }

    @Test
    void aWorldWithSeveralFaultsIsALineForEachNamingTheSweepFile() throws Exception {
        Path broken = dir.resolve("broken.xml");
        Files.writeString(broken, Files.readString(WANDER).replace("timeStepMs=\"100\"", "timeStepMs=\"-1\"")
                .replace("x=\"1\" y=\"1\"", "x=\"99\" y=\"1\""));
        Path f = write("<sweep world=\"broken.xml\" steps=\"5\"><seeds from=\"1\" to=\"3\"/></sweep>");
        SweepException e = assertThrows(SweepException.class, () -> SweepFile.read(f));
        List<String> lines = e.getMessage().lines().toList();
        assertEquals(2, lines.size(), e.getMessage());
        assertTrue(lines.get(0).startsWith(f + ": " + broken + ":") && lines.get(0).endsWith("timeStepMs must be > 0, "
                + "got -1"), e.getMessage());
        assertTrue(lines.get(1).startsWith(f + ": " + broken + ":") && lines.get(1).contains("does not fit inside the "
                + "arena"), e.getMessage());
    }

    @Test
    void aResubmissionsArraysHoldOnlyTheMissingRunsUnderMaxArraySize() {
        assertEquals(Map.of(0, "0-3,5,9-11"), Slurm.arrays(List.of(0, 1, 2, 3, 5, 9, 10, 11), 1001));
        assertEquals(List.of(0, 4, 8), List.copyOf(Slurm.arrays(List.of(1, 2, 3, 4, 9, 11), 4).keySet()));
        assertEquals(List.of("1-3", "0", "1,3"), List.copyOf(Slurm.arrays(List.of(1, 2, 3, 4, 9, 11), 4).values()),
                "each array's indices are the runs less its offset: run 9 is offset 8's index 1");
    }

    @Test
    void aTasksListOfRunsIsReadBackAsItsRunsAndABadOneIsRefused() throws Exception {
        assertEquals(List.of(0, 1, 2, 5, 9, 10, 11), SweepMain.Task.indices(Slurm.ranges(List.of(0, 1, 2, 5, 9, 10,
                11)), 12));
        for (String bad : List.of("3-1", "x", "1,,2", "-4", "1,2,", "0-12")) {
            SweepException e = org.junit.jupiter.api.Assertions.assertThrows(SweepException.class,
                    () -> SweepMain.Task.indices(bad, 12));
            assertTrue(e.getMessage().startsWith("sweep: --runs"), e.getMessage());
        }
    }

    @Test
    void aSlurmTaskRunsManyShortRunsButOneLongOneByDefault() throws Exception {
        int shortRuns = Slurm.runsPerTask(SweepFile.read(write(sweep("", "<seeds from=\"1\" to=\"40\"/>"))));
        assertTrue(shortRuns >= 100 && shortRuns <= 300, "100 steps of 6 robots, a tenth of a second or so: " + shortRuns);
        Path longer = write("<sweep world=\"" + WANDER + "\" steps=\"5000000\"><seeds from=\"1\" to=\"4\"/></sweep>");
        assertEquals(1, Slurm.runsPerTask(SweepFile.read(longer)), "a run of minutes is a task of its own");
    }

    @Test
    void columnsAreNeverTakenTwice() throws Exception {
        String e = refused(sweep("", "<seeds from=\"1\" to=\"2\"/><param name=\"seed\" values=\"1 2\"/>"));
        assertTrue(e.contains("a row's own column or a built-in metric has that name (the seeds are <seeds"), e);
        assertEquals("report.seed", RunMetrics.reportColumn("seed"));
        assertEquals("report.distance_m", RunMetrics.reportColumn("distance_m"));
        assertEquals("turns", RunMetrics.reportColumn("turns"));
        Path rows = Files.createDirectories(dir.resolve("rows"));
        String header = "index,seed,repetition,status,exit_code\n";
        Files.writeString(rows.resolve("run-000017.csv"), header + "3,1,1,ok,0\n");
        java.io.IOException bad = assertThrows(java.io.IOException.class, () -> Row.read(rows.resolve("run-000017.csv")));
        assertTrue(bad.getMessage().endsWith("index '3' is not this row file's run"), bad.getMessage());
        Files.writeString(rows.resolve("run-000003.csv"), header + "3,1,1,ok,0\n");
        assertEquals(3, Row.read(rows.resolve("run-000003.csv")).index());
        Files.writeString(rows.resolve("run-000004.csv"), header + "4,1,1,fine,0\n");
        assertTrue(assertThrows(java.io.IOException.class, () -> Row.read(rows.resolve("run-000004.csv"))).getMessage()
                .endsWith("not a run's row (status 'fine', exit_code '0')"));
        Files.write(rows.resolve("run-000005.csv"), new byte[] {'i', (byte) 0xff, '\n'});
        assertEquals(rows.resolve("run-000005.csv") + ": not a run's row (bytes that are not UTF-8)", assertThrows(
                java.io.IOException.class, () -> Row.read(rows.resolve("run-000005.csv"))).getMessage());
        Row odd = new Row(Map.of("index", "6", "status", "ok", "distance_m", "abc"));
        assertTrue(Double.isNaN(Tables.number(odd, "distance_m")), "not a number: left out");
    }

    @Test
    void theCommandRefusesABadFileWithExitTwoAndRunsNothing() throws Exception {
        Path f = write(sweep("", "<seeds from=\"4\" to=\"3\"/>"));
        Path out = dir.resolve("out");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream was = System.err;
        int code;
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            code = SweepMain.commandLine().execute(f.toString(), "--out", out.toString());
        } finally {
            System.setErr(was);
        }
        assertEquals(2, code);
        assertEquals(1, err.toString(StandardCharsets.UTF_8).lines().count(), err.toString(StandardCharsets.UTF_8));
        assertFalse(Files.exists(out), "nothing written");
    }
}
