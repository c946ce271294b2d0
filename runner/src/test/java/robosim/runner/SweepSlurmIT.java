package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A sweep through a real Slurm (a one-node cluster on this machine, started by scripts/slurm-cluster.sh from
 * Debian's packages), its runs in chunks (two tasks, of three runs and of one, each chunk in one warm JVM), gives the
 * same runs.csv as on this machine's pool, but for the wall-time column (which runs
 * a resubmission with --resume submits is SweepFileTest's: the arrays for the missing rows). CI installs Slurm and requires this test
 * ({@code ROBOSIM_SLURM_TEST=required}); elsewhere, without Slurm installed, it is skipped saying why.
 */
class SweepSlurmIT {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();
    private static final Path CLUSTER = REPO.resolve("scripts/slurm-cluster.sh");
    /** The sweep: 2 speeds x 2 seeds of test-envs/wander.xml, 100 steps each (a grid, as small as shows one). */
    private static final String SPEC = "<sweep world=\"" + REPO.resolve("test-envs/wander.xml") + "\" steps=\"100\">"
            + "<seeds from=\"1\" to=\"2\"/><param name=\"speed\" values=\"300 900\"/></sweep>";
    private static boolean startedHere;

    @TempDir
    Path tmp;

    @BeforeAll
    static void startTheCluster() throws Exception {
        boolean installed = Files.isExecutable(Path.of("/usr/sbin/slurmctld")) && Files.isExecutable(Path.of("/usr/bin/sbatch"));
        boolean root = "root".equals(System.getProperty("user.name"));
        if (!installed || !root) {
            assertTrue(!"required".equals(System.getenv("ROBOSIM_SLURM_TEST")),
                    "ROBOSIM_SLURM_TEST=required, but Slurm is not installed or this is not root (scripts/slurm-cluster.sh "
                            + "install and start need root)");
            Assumptions.abort("Slurm is not installed here, or this is not root (scripts/slurm-cluster.sh install and "
                    + "start need root; CI has both)");
        }
        startedHere = cluster("status") != 0;
        assertEquals(0, cluster("start"), "scripts/slurm-cluster.sh start");
    }

    @AfterAll
    static void stopTheCluster() throws Exception {
        if (startedHere) {
            cluster("stop");
        }
    }

    /** Runs scripts/slurm-cluster.sh with {@code command}; its exit code (its output goes to ours). */
    private static int cluster(String command) throws Exception {
        Process p = new ProcessBuilder(CLUSTER.toString(), command).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.INHERIT).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "slurm-cluster.sh " + command + " did not end within 120 s");
        return p.exitValue();
    }

    private ScriptRun sweep(String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(REPO.resolve("scripts/sweep.sh").toString()));
        cmd.addAll(List.of(args));
        return ScriptRun.within(600, tmp, Map.of(), tmp, cmd.toArray(String[]::new));
    }

    private static List<String> withoutWallTime(Path runsCsv) throws Exception {
        List<String> out = new ArrayList<>();
        for (String line : Files.readAllLines(runsCsv)) {
            out.add(line.substring(0, line.lastIndexOf(',')));
        }
        return out;
    }

    @Test
    @org.junit.jupiter.api.Timeout(value = 900, unit = TimeUnit.SECONDS) // (two sweeps of 4 runs, one through Slurm)
    void aSlurmSweepGivesTheLocalSweepsRows() throws Exception {
        Path spec = tmp.resolve("spec.xml");
        Files.writeString(spec, SPEC);
        Path local = tmp.resolve("local");
        Path slurm = tmp.resolve("slurm");
        ScriptRun here = sweep(spec.toString(), "--out", local.toString());
        assertEquals(0, here.exit(), here.stderr());
        ScriptRun there = sweep(spec.toString(), "--out", slurm.toString(), "--slurm", "--wait", "--max-parallel", "2",
                "--partition", "robosim", "--runs-per-task", "3");
        assertEquals(0, there.exit(), there.stderr());
        assertTrue(there.stderr().contains("submitted job array"), there.stderr());
        assertTrue(there.stderr().contains("(2 tasks of up to 3 runs, at most 2 at once)"), there.stderr());
        String tasks = String.join("\n", Files.readAllLines(slurm.resolve("slurm/task-1.sh")));
        assertTrue(tasks.contains("chunks=(0-2 3)"), tasks);
        List<String> rows = withoutWallTime(local.resolve("runs.csv"));
        assertEquals(5, rows.size(), String.join("\n", rows));
        assertTrue(rows.get(0).startsWith("index,seed,repetition,speed,status,exit_code,steps,"), rows.get(0));
        assertEquals(rows, withoutWallTime(slurm.resolve("runs.csv")), "the same runs, the same rows");
        assertTrue(Files.exists(slurm.resolve("plots/distance_m-vs-speed.png")), "the gather job made the plots");

        ScriptRun status = sweep("status", slurm.toString());
        assertEquals(0, status.exit(), status.stderr());
        assertTrue(status.stdout().contains("4 of 4 runs have rows, 0 failed"), status.stdout());
    }
}
