package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The scripts' class-data archives, end to end (runner/README.md, "How the scripts behave"): a second
 * {@code headless.sh} run maps, in the runner's JVM and in the Environment's, the classes the first run
 * archived at its exit, and neither run says a word about archives.
 */
class ClassDataArchivesIT {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();
    private static final Pattern JAVA = Pattern.compile("^running .* on Java (\\d+) ", Pattern.MULTILINE);
    /** What the JVM's class+load log says of a class it mapped from the dynamic archive. */
    private static final String MAPPED = "source: shared objects file (top)";

    @TempDir
    Path tmp;

    @Test
    void theSecondRunMapsWhatTheFirstArchivedAndNeitherSaysSo() throws Exception {
        Path runnerClasses = tmp.resolve("runner-classes.log");
        Path environmentClasses = tmp.resolve("environment-classes.log");
        // (these logging options are part of the archives' keys: this test's archives are its own)
        Map<String, String> env = Map.of("ROBOSIM_JAVA_OPTS", "-Xlog:class+load:file=" + runnerClasses);
        // (robots in one process, geometry in the Environment: the runner's JVM and two children)
        String[] headless = {REPO.resolve("scripts/headless.sh").toString(), "--robots-in-one-process",
            "--no-geometry", "--env", REPO.resolve("test-envs/bench-10.xml").toString(), "--steps", "20",
            "--environment-jvm-opts", "-XX:+UseSerialGC -Xlog:class+load:file=" + environmentClasses};

        ScriptRun first = ScriptRun.of(tmp, env, tmp, headless);
        assertEquals(0, first.exit(), "stderr: " + first.stderr());
        Matcher java = JAVA.matcher(first.stdout());
        assertTrue(java.find(), first.stdout());
        assumeTrue(Integer.parseInt(java.group(1)) >= 19, "no archives on Java " + java.group(1));
        assertEquals(0, mapped(runnerClasses), "the first run has no archive yet");

        ScriptRun second = ScriptRun.of(tmp, env, tmp, headless);
        assertEquals(0, second.exit(), "stderr: " + second.stderr());
        assertTrue(mapped(runnerClasses) > 1000, "the runner's JVM should map the classes of the first run");
        assertTrue(mapped(environmentClasses) > 1000, "the Environment's JVM should map the classes of the first run");
        for (ScriptRun run : List.of(first, second)) {
            List<String> said = run.stderr().lines()
                    .filter(l -> l.contains("[cds") || l.contains("[warning]") || l.toLowerCase().contains("archive"))
                    .toList();
            assertEquals(List.of(), said, "nothing about archives on stderr");
        }
    }

    private static long mapped(Path classLog) throws IOException {
        try (var lines = Files.lines(classLog)) {
            return lines.filter(l -> l.contains(MAPPED)).count();
        }
    }
}
