package robosim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robosim.sweep.SweepCommand.spec;
import static robosim.sweep.SweepCommand.sweep;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A sweep's runs that fail, end to end: a failed run is a row with its reason, said once, and the sweep goes on;
 * runs failing alike from the start stop it; a run that breaks its warm worker costs that row alone; a report the
 * file names and no robot made fails the sweep, saying so; what over="..." takes of the robots' reports.
 */
class SweepFailuresTest {
    @TempDir
    Path dir;



    @Test
    void aFailedRunIsARowWithItsExitCodeAndReasonSaidOnceAndTheSweepGoesOn() throws Exception {
        Path out = dir.resolve("failed");
        // (Wander reads its parameter speed as a number: each robot's control code fails at once)
        SweepCommand r = sweep(spec(dir, SweepFileTest.WANDER.toString(), "<param name=\"speed\" values=\"fast\"/>").toString(),
                "--out", out.toString());
        assertEquals(1, r.code(), r.err());
        List<String> runs = Files.readAllLines(out.resolve("runs.csv"));
        assertEquals(3, runs.size(), "both runs have rows: " + runs);
        String reason = "parameter speed is 'fast', not a number";
        for (String line : runs.subList(1, 3)) {
            List<String> f = SweepCommand.fields(line);
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
    void whenTheFirstRunsAllFailAlikeTheSweepStopsSaysWhyAndRemovesTheirRows() throws Exception {
        Path spec = dir.resolve("doomed.xml");
        Files.writeString(spec, "<sweep world=\"" + SweepFileTest.WANDER + "\" steps=\"50\"><seeds from=\"1\" "
                + "to=\"8\"/><param name=\"speed\" values=\"fast\"/></sweep>");
        Path out = dir.resolve("doomed");
        SweepCommand r = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1");
        assertEquals(1, r.code(), r.err());
        assertTrue(r.err().contains("the first 3 runs all failed: ") && r.err().contains("parameter speed is 'fast'"),
                r.err());
        assertTrue(r.err().contains("0 of 8 runs have rows"), r.err());
    }

    @Test
    void aReportNoRobotMadeWarnsAndFailsTheSweepAndOverTakesTheRobotsValuesAsAsked() throws Exception {
        Path spec = spec(dir, SweepFileTest.WANDER.toString(), "<metrics><metric report=\"turns\"/><metric report=\"turns\" "
                + "over=\"mean\"/><metric report=\"turns\" over=\"max\"/><metric report=\"turns\" over=\"each\"/>"
                + "<metric report=\"turnz\"/></metrics>");
        Path out = dir.resolve("over");
        SweepCommand r = sweep(spec.toString(), "--out", out.toString());
        assertEquals(1, r.code(), r.err());
        assertTrue(r.err().contains("no robot reported 'turnz' (reported: turns)"), r.err());
        assertTrue(r.err().contains("no robot reported 'turnz' in any run"), r.err());
        List<String> runs = Files.readAllLines(out.resolve("runs.csv"));
        List<String> header = SweepCommand.fields(runs.get(0));
        for (String line : runs.subList(1, runs.size())) {
            List<String> f = SweepCommand.fields(line);
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
        SweepCommand r = sweep(spec.toString(), "--out", out.toString(), "--jobs", "1");
        assertEquals(1, r.code(), r.err());
        List<String> runs = Files.readAllLines(out.resolve("runs.csv"));
        assertEquals(5, runs.size(), String.join("\n", runs));
        List<String> stand = SweepCommand.fields(runs.get(1));
        assertEquals(List.of("stand", "ok", "0"), stand.subList(3, 6), runs.get(1));
        List<String> exit = SweepCommand.fields(runs.get(2));
        assertEquals(List.of("exit", "failed", "7"), exit.subList(3, 6), runs.get(2));
        assertTrue(exit.get(exit.size() - 2).contains("its warm JVM exited with code 7 during the run"), runs.get(2));
        List<String> leave = SweepCommand.fields(runs.get(3));
        assertEquals(List.of("leave", "failed"), leave.subList(3, 5), runs.get(3));
        // (its control code ends as the run does; on a loaded machine it may still be ending when it is looked at)
        String why = leave.get(leave.size() - 2);
        assertTrue(why.contains("the run left threads running 5 s after its end: never-ends")
                || why.contains("the control code of b1 was still running after the run's end"), runs.get(3));
        assertEquals(SweepCommand.fields(runs.get(1)).subList(4, 10), SweepCommand.fields(runs.get(4)).subList(4, 10),
                "the run after them, in a fresh worker, is the first's again (its mode stands still too)");
        assertTrue(r.err().contains("4 of 4 runs have rows, 2 failed"), r.err());
    }
}
