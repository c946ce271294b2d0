package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Ctrl-C (SIGINT) or SIGTERM on scripts/sweep.sh: every run stops at once, no run is left running, the rows written
 * stay whole and the tables are made from them (that --resume then runs only the rest is SweepTest's). SIGINT only
 * where this JVM does not ignore it: a process started in the background of a non-interactive shell ignores it, and
 * so do its children (the sweep too, which cannot undo that); SIGTERM stops it alike.
 */
class SweepStopIT {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();

    @TempDir
    Path tmp;

    private static List<Path> rows(Path out) throws Exception {
        List<Path> rows = new ArrayList<>();
        if (Files.isDirectory(out.resolve("rows"))) {
            try (DirectoryStream<Path> s = Files.newDirectoryStream(out.resolve("rows"))) {
                s.forEach(rows::add);
            }
        }
        return rows;
    }

    @Test
    void sigtermStopsEveryRunAndKeepsTheRowsWritten() throws Exception {
        stopsEveryRunAndKeepsTheRowsWritten("TERM", 143);
    }

    @Test
    void ctrlCStopsEveryRunAndKeepsTheRowsWritten() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeFalse(ignores(2), "SIGINT is ignored here (and in every child): started "
                + "in the background of a non-interactive shell");
        stopsEveryRunAndKeepsTheRowsWritten("INT", 130);
    }

    /** Whether this process ignores signal {@code number} (Linux: /proc/self/status's SigIgn); false where unknown. */
    private static boolean ignores(int number) throws Exception {
        Path status = Path.of("/proc/self/status");
        if (!Files.exists(status)) {
            return false;
        }
        for (String line : Files.readAllLines(status)) {
            if (line.startsWith("SigIgn:")) {
                return (Long.parseUnsignedLong(line.substring(7).trim(), 16) & (1L << (number - 1))) != 0;
            }
        }
        return false;
    }

    private void stopsEveryRunAndKeepsTheRowsWritten(String signal, int exit) throws Exception {
        // two fast runs (seeds 1 and 2), then two that take 200 x 100 ms: Ctrl-C comes after the first row, before the end
        Path world = tmp.resolve("world.xml");
        Files.writeString(world, "<environment timeStepMs=\"100\"><param name=\"dawdle_ms\" value=\"0\"/>"
                + "<arena width=\"4\" height=\"4\"/><robots><robot name=\"d\" type=\"Scout\" control=\""
                + Dawdler.class.getName() + "\" x=\"2\" y=\"2\"/></robots></environment>");
        Path spec = tmp.resolve("spec.xml");
        Files.writeString(spec, "<sweep world=\"world.xml\" steps=\"200\"><seeds from=\"1\" to=\"2\"/>"
                + "<param name=\"dawdle_ms\" values=\"0 100\"/></sweep>");
        Path out = tmp.resolve("out");
        ProcessBuilder builder = new ProcessBuilder("setsid", REPO.resolve("scripts/sweep.sh").toString(),
                spec.toString(), "--out", out.toString(), "--jobs", "1").redirectErrorStream(true);
        builder.environment().put("ROBOSIM_CLASSPATH", Path.of("target/test-classes").toAbsolutePath().toString());
        Process sweep = builder.start();
        StringBuilder said = new StringBuilder();
        try (BufferedReader lines = new BufferedReader(new InputStreamReader(sweep.getInputStream(),
                StandardCharsets.UTF_8))) {
            String line = lines.readLine();
            while (line != null && !line.startsWith("sweep: [")) { // (the progress line after the first row: an event)
                said.append(line).append('\n');
                line = lines.readLine();
            }
            assertTrue(line != null, "the sweep ended before its first row: " + said);
            new ProcessBuilder("kill", "-" + signal, Long.toString(sweep.pid())).start().waitFor();
            for (; line != null; line = lines.readLine()) { // (to its end: the output closes when it exits)
                said.append(line).append('\n');
            }
            assertTrue(sweep.waitFor(60, TimeUnit.SECONDS), "the sweep did not stop within 60 s of SIG" + signal);
            assertEquals(exit, sweep.exitValue(), said.toString());
            assertTrue(said.indexOf("sweep: stopped: ") >= 0 && said.indexOf("--resume runs the rest") >= 0,
                    said.toString());
            assertTrue(ProcessHandle.allProcesses().noneMatch(h -> h.info().commandLine().orElse("")
                    .contains(out.toString())), "a run of the sweep is still running");
        } finally {
            sweep.destroyForcibly();
        }
        List<Path> kept = rows(out);
        assertFalse(kept.isEmpty());
        assertTrue(kept.size() <= 2, "stopped before the slow runs ended: " + kept);
        for (Path row : kept) {
            assertTrue(row.getFileName().toString().matches("run-\\d{6}\\.csv"), "no half-written row: " + row);
            assertEquals(2, Files.readAllLines(row).size(), row.toString());
        }
        assertEquals(kept.size() + 1, Files.readAllLines(out.resolve("runs.csv")).size(), "the tables hold the rows kept");
    }
}
