package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The scripts' class-data archives, end to end (runner/README.md, "How the scripts behave"): a later
 * {@code headless.sh} run maps, in the runner's JVM and in the Environment's, RoboSim's classes that the first
 * run trained on (JDK 19-24: the dynamic archive the first run wrote at its exit, mapped by the second; JDK 25
 * and later: the AOT cache assembled in the background from the first run's configuration, mapped once that is
 * done), and no run says a word about archives.
 */
class ClassDataArchivesIT {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();
    private static final Pattern JAVA = Pattern.compile("^running .* on Java (\\d+) ", Pattern.MULTILINE);
    /** What the JVM's class+load log says of a class it mapped from an archive (the JDK's own, the dynamic one, the AOT cache). */
    private static final String MAPPED = "source: shared objects file";
    private static final long LONG_S = 120;

    @TempDir
    Path tmp;

    @Test
    void aLaterRunMapsWhatTheFirstTrainedOnAndNoneSaysSo() throws Exception {
        Path runnerClasses = tmp.resolve("runner-classes.log");
        Path environmentClasses = tmp.resolve("environment-classes.log");
        // (these logging options are part of the archives' keys: this test's archives are its own)
        // (on here: the other script tests run with ROBOSIM_CDS=off, runner/pom.xml)
        Map<String, String> env = Map.of("ROBOSIM_JAVA_OPTS", "-Xlog:class+load:file=" + runnerClasses, "ROBOSIM_CDS", "on");
        // (robots in one process, geometry in the Environment: the runner's JVM and two children)
        String[] headless = {REPO.resolve("scripts/headless.sh").toString(), "--robots-in-one-process",
            "--no-geometry", "--env", REPO.resolve("test-envs/bench-10.xml").toString(), "--steps", "20",
            "--environment-jvm-opts", "-XX:+UseSerialGC -Xlog:class+load:file=" + environmentClasses};

        List<ScriptRun> runs = new ArrayList<>();
        runs.add(ScriptRun.of(tmp, env, tmp, headless));
        assertEquals(0, runs.get(0).exit(), "stderr: " + runs.get(0).stderr());
        Matcher java = JAVA.matcher(runs.get(0).stdout());
        assertTrue(java.find(), runs.get(0).stdout());
        int feature = Integer.parseInt(java.group(1));
        assumeTrue(feature >= 19, "no archives on Java " + feature);
        assertEquals(0, mappedOwn(runnerClasses), "the first run has no archive yet");

        if (feature >= 25) {
            // the second start of the runner's key has its cache assembled in the background (it runs without): a
            // start in one JVM will do; the Environment's was assembled as the first run's Environment ended
            runs.add(ScriptRun.of(tmp, env, tmp, REPO.resolve("scripts/headless.sh").toString(), "--one-jvm", "--env",
                    REPO.resolve("test-envs/bench-10.xml").toString(), "--steps", "20"));
            assertEquals(0, runs.get(1).exit(), "stderr: " + runs.get(1).stderr());
            awaitAssemblers();
        }
        runs.add(ScriptRun.of(tmp, env, tmp, headless));
        assertEquals(0, runs.get(runs.size() - 1).exit(), "stderr: " + runs.get(runs.size() - 1).stderr());
        assertTrue(mappedOwn(runnerClasses) > 50, "the runner's JVM should map RoboSim's classes: " + mappedOwn(runnerClasses) + " " + listing());
        assertTrue(mappedOwn(environmentClasses) > 50, "the Environment's JVM should map RoboSim's classes");
        for (ScriptRun run : runs) {
            List<String> said = run.stderr().lines()
                    .filter(l -> l.contains("[cds") || l.contains("[aot") || l.contains("[warning]")
                            || l.toLowerCase().contains("archive") || l.contains("AOT"))
                    .toList();
            assertEquals(List.of(), said, "nothing about archives on stderr");
        }
    }

    private static String listing() throws IOException {
        try (Stream<Path> files = Files.walk(REPO.resolve("runner/target/cds"), 2)) {
            return files.map(p -> p.getFileName().toString()).toList().toString();
        }
    }

    /** How many of RoboSim's classes the JVM that wrote {@code classLog} (its last run) mapped from an archive. */
    private static long mappedOwn(Path classLog) throws IOException {
        try (var lines = Files.lines(classLog)) {
            return lines.filter(l -> l.contains(" robosim.") && l.contains(MAPPED)).count();
        }
    }

    /** Waits for every AOT cache assembler (a claim with a pid in its {@code .start}) under runner/target/cds to end. */
    private static void awaitAssemblers() throws Exception {
        List<Path> starts;
        try (Stream<Path> files = Files.walk(REPO.resolve("runner/target/cds"), 2)) {
            starts = files.filter(p -> p.toString().endsWith(".start")).toList();
        }
        for (Path start : starts) {
            String pid;
            try {
                pid = Files.readString(start).strip();
            } catch (IOException gone) {
                continue;
            }
            if (!pid.isEmpty()) {
                var assembler = ProcessHandle.of(Long.parseLong(pid));
                if (assembler.isPresent()) {
                    assembler.get().onExit().get(LONG_S, TimeUnit.SECONDS);
                }
            }
        }
    }
}
