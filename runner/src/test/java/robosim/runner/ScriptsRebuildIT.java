package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * scripts/common.sh's rebuild rule, on a copy of it in a made-up repository whose ./mvnw only records
 * that it was called (and rewrites the runner jar, as `package` does): a build starts exactly when a
 * module's main source or pom is newer than the runner jar, for every module the parent pom lists.
 */
class ScriptsRebuildIT {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();
    private static final Instant BUILT = Instant.now().minusSeconds(600);

    @TempDir
    Path repo;

    @TempDir
    Path logs;

    @BeforeEach
    void makeRepository() throws IOException {
        Files.createDirectories(repo.resolve("scripts"));
        Files.copy(REPO.resolve("scripts/common.sh"), repo.resolve("scripts/common.sh"));
        script("scripts/probe.sh", """
                #!/usr/bin/env bash
                set -euo pipefail
                source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
                robosim_build_if_stale
                echo ready
                """);
        script("scripts/javaprobe.sh", """
                #!/usr/bin/env bash
                # A probe that starts a Java main: scripts/javaprobe.sh [--help]
                source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
                robosim_java robosim.NoSuchMain "$@"
                """);
        script("mvnw", """
                #!/usr/bin/env bash
                echo "$*" >> mvnw.calls
                echo "[INFO] Building RoboSim alpha 0.1.0-SNAPSHOT                        [1/2]"
                echo "[INFO] --- compiler:3.13.0:compile (default-compile) @ alpha ---"
                echo "[INFO] Building RoboSim robot-api 0.1.0-SNAPSHOT                    [2/2]"
                sleep 1 # a build takes a while: scripts started together overlap it
                [ "${FAKE_BUILD_FAILS:-}" = 1 ] && { echo "[ERROR] COMPILATION ERROR"; exit 1; }
                touch runner/target/runner-0.1.jar
                """);
        write("pom.xml", "<project><modules>\n  <module>alpha</module>\n  <module>robot-api</module>\n"
                + "  <module>runner</module>\n</modules></project>\n");
        for (String f : List.of("alpha/pom.xml", "alpha/src/main/java/A.java", "alpha/src/test/java/ATest.java",
                "robot-api/pom.xml", "robot-api/src/main/java/B.java", "runner/pom.xml")) {
            write(f, "x\n");
        }
        Files.createDirectories(repo.resolve("runner/target/lib"));
        write("runner/target/runner-0.1.jar", "jar\n");
        try (var all = Files.walk(repo)) {
            for (Path p : all.toList()) {
                Files.setLastModifiedTime(p, FileTime.from(BUILT.minusSeconds(60)));
            }
        }
        Files.setLastModifiedTime(repo.resolve("runner/target/runner-0.1.jar"), FileTime.from(BUILT));
    }

    @Test
    void nothingNewerNoBuild() throws Exception {
        ScriptRun run = probe(Map.of());
        assertEquals(0, run.exit(), run.stderr());
        assertEquals("ready\n", run.stdout());
        assertEquals("", run.stderr());
        assertFalse(Files.exists(repo.resolve("mvnw.calls")));
    }

    @Test
    void aNewerSourceInAModuleOnlyThePomNamesRebuildsOnceWithOneLine() throws Exception {
        touch("robot-api/src/main/java/B.java");
        ScriptRun run = probe(Map.of());
        assertEquals(0, run.exit(), run.stderr());
        assertEquals("ready\n", run.stdout());
        assertEquals(List.of("RoboSim sources changed since the last build (robot-api/src/main/java/B.java): "
                + "rebuilding (./mvnw package -DskipTests; a first build fetches Maven and the libraries) ...",
                "  building RoboSim alpha [1/2]", "  building RoboSim robot-api [2/2]"), run.stderr().lines().toList());
        assertEquals(List.of("-B -ntp package -DskipTests"), Files.readAllLines(repo.resolve("mvnw.calls")));
        assertEquals("", probe(Map.of()).stderr(), "built: no second build");
        assertEquals(1, Files.readAllLines(repo.resolve("mvnw.calls")).size());
    }

    @Test
    void scriptsStartedTogetherBuildOnce() throws Exception {
        touch("alpha/src/main/java/A.java");
        List<Process> probes = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            probes.add(new ProcessBuilder(repo.resolve("scripts/probe.sh").toString()).directory(repo.toFile())
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start());
        }
        for (Process p : probes) {
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), "probe did not end");
            assertEquals(0, p.exitValue());
        }
        assertEquals(1, Files.readAllLines(repo.resolve("mvnw.calls")).size(), "one build for three scripts");
    }

    @Test
    void aNewerModulePomRebuildsATestSourceDoesNot() throws Exception {
        touch("alpha/src/test/java/ATest.java");
        assertEquals("", probe(Map.of()).stderr());
        touch("alpha/pom.xml");
        assertTrue(probe(Map.of()).stderr().contains("(alpha/pom.xml): rebuilding"));
    }

    @Test
    void nothingBuiltBuilds() throws Exception {
        Files.delete(repo.resolve("runner/target/runner-0.1.jar"));
        ScriptRun run = probe(Map.of());
        assertTrue(run.stderr().startsWith("RoboSim is not built yet: rebuilding"), run.stderr());
        assertEquals("ready\n", run.stdout());
    }

    @Test
    void helpBuildsNothingEvenWhenTheBuildIsStaleOrMissing() throws Exception {
        touch("alpha/src/main/java/A.java");
        ScriptRun stale = ScriptRun.of(repo, Map.of(), logs, repo.resolve("scripts/javaprobe.sh").toString(), "--help");
        assertFalse(stale.stderr().contains("rebuilding"), stale.stderr());
        Files.delete(repo.resolve("runner/target/runner-0.1.jar"));
        ScriptRun missing = ScriptRun.of(repo, Map.of(), logs, repo.resolve("scripts/javaprobe.sh").toString(), "-h");
        assertEquals(0, missing.exit(), missing.stderr());
        assertTrue(missing.stdout().startsWith("A probe that starts a Java main: scripts/javaprobe.sh [--help]"),
                missing.stdout());
        assertTrue(missing.stdout().contains("(RoboSim is not built yet: its full usage is printed once it is"),
                missing.stdout());
        assertFalse(Files.exists(repo.resolve("mvnw.calls")), "no build for --help");
    }

    @Test
    void aFailedBuildEndsTheScriptWithExitOne() throws Exception {
        touch("alpha/src/main/java/A.java");
        ScriptRun run = probe(Map.of("FAKE_BUILD_FAILS", "1"));
        assertEquals(1, run.exit(), run.stderr());
        assertEquals("", run.stdout(), "the build's output goes to stderr and the script stops");
        List<String> lines = run.stderr().lines().toList();
        assertEquals(List.of("[ERROR] COMPILATION ERROR", "probe: the build failed (its errors are above); nothing was "
                + "started"), lines.subList(lines.size() - 2, lines.size()), run.stderr());
    }

    private ScriptRun probe(Map<String, String> env) throws Exception {
        return ScriptRun.of(repo, env, logs, repo.resolve("scripts/probe.sh").toString());
    }

    private void touch(String file) throws IOException {
        Files.setLastModifiedTime(repo.resolve(file), FileTime.from(BUILT.plusSeconds(60)));
    }

    private void write(String file, String text) throws IOException {
        Files.createDirectories(repo.resolve(file).getParent());
        Files.writeString(repo.resolve(file), text);
    }

    private void script(String file, String text) throws IOException {
        write(file, text);
        Files.setPosixFilePermissions(repo.resolve(file), PosixFilePermissions.fromString("rwxr-xr-x"));
    }
}
