package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.Execution;
import org.junit.jupiter.api.parallel.ExecutionMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The mechanics of scripts/*.sh, run as a user runs them (after package, so the build is newer than
 * every source and no script starts a build of its own): --help and -h on every script, bad options
 * on the pure-bash ones, and --classpath / ROBOSIM_CLASSPATH reaching the processes a script starts.
 */
class ScriptsIT {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();
    /** A script that hands its arguments to a Java main (picocli) or to another script. */
    private static final Pattern DELEGATES = Pattern.compile("robosim_java |exec scripts/");

    @TempDir
    Path tmp;

    static Stream<Path> scripts() throws IOException {
        try (Stream<Path> files = Files.list(REPO.resolve("scripts"))) {
            List<Path> all = files.filter(f -> f.toString().endsWith(".sh")).sorted().toList();
            assertTrue(all.size() > 10, "scripts/ should hold the launch scripts, found " + all);
            return all.stream();
        }
    }

    static Stream<Path> pureBashScripts() throws IOException {
        List<Path> pure = new ArrayList<>();
        for (Path s : scripts().toList()) {
            if (!DELEGATES.matcher(Files.readString(s)).find()) {
                pure.add(s);
            }
        }
        return pure.stream();
    }

    @ParameterizedTest
    @MethodSource("scripts")
    @Execution(ExecutionMode.CONCURRENT) // (each starts a short process; none writes anything)
    void helpPrintsUsageRunsNothingAndWritesNothing(Path script) throws Exception {
        String name = script.getFileName().toString();
        // (-h too where the script reads its options itself; a Java main's are picocli's, -h and --help alike: one is
        // tried, environment.sh's)
        boolean own = !DELEGATES.matcher(Files.readString(script)).find() || name.equals("environment.sh");
        for (String help : own ? List.of("--help", "-h") : List.of("--help")) {
            String before = gitStatus();
            ScriptRun run = ScriptRun.of(REPO, Map.of(), tmp, script.toString(), help);
            assertEquals(0, run.exit(), name + " " + help + " exit; stderr: " + run.stderr());
            assertTrue(run.stdout().contains(name), name + " " + help + " should print its usage: " + run.stdout());
            assertTrue(!run.stdout().contains("null"), name + " " + help + ": a text the help lost (a ${NAME} of a "
                    + "description read as a variable prints null): " + run.stdout());
            assertTrue(!run.stderr().contains("rebuilding"), name + " started a build: " + run.stderr());
            assertEquals(before, gitStatus(), name + " " + help + " changed the repository");
        }
    }

    @ParameterizedTest
    @MethodSource("pureBashScripts")
    @Execution(ExecutionMode.CONCURRENT)
    void anUnknownOptionIsOneLineAndExitTwo(Path script) throws Exception {
        String name = script.getFileName().toString();
        String before = gitStatus();
        ScriptRun run = ScriptRun.of(REPO, Map.of(), tmp, script.toString(), "--no-such-option");
        assertEquals(2, run.exit(), name + " exit; stderr: " + run.stderr());
        List<String> lines = run.stderr().lines().toList();
        assertEquals(1, lines.size(), name + " should say what is wrong on one line: " + run.stderr());
        assertTrue(lines.get(0).contains(name.replace(".sh", "")) && lines.get(0).contains("--no-such-option"),
                name + ": the line should name the script and the option: " + lines.get(0));
        assertEquals("", run.stdout(), name + " printed on stdout");
        assertEquals(before, gitStatus(), name + " changed the repository");
    }

    @Test
    void aClassPathInRobosimJavaOptsIsRefusedWithAPointerToClasspath() throws Exception {
        ScriptRun run = ScriptRun.of(REPO, Map.of("ROBOSIM_JAVA_OPTS", "-Xmx64m -cp /tmp"), tmp,
                "scripts/geometry.sh", "--help");
        assertEquals(2, run.exit(), run.stderr());
        assertEquals(1, run.stderr().lines().count(), run.stderr());
        assertTrue(run.stderr().contains("--classpath"), run.stderr());
    }

    @Test
    void aMissingClassPathEntryIsNamed() throws Exception {
        ScriptRun run = ScriptRun.of(tmp, Map.of(), tmp, REPO.resolve("scripts/robot.sh").toString(),
                "--classpath", "not-there", "--help");
        assertEquals(2, run.exit(), run.stderr());
        assertEquals(1, run.stderr().lines().count(), run.stderr());
        assertTrue(run.stderr().contains(tmp.resolve("not-there").toString()), run.stderr());
    }

    /** A control class that exists only in a temporary directory drives the robot of headless.sh's child. */
    @Test
    void relativeClasspathReachesTheRobotProcesses() throws Exception {
        writeWorldAndControlClass();
        ScriptRun run = ScriptRun.of(tmp, Map.of(), tmp, REPO.resolve("scripts/headless.sh").toString(),
                "--env", "world.xml", "--no-geometry", "--steps", "20", "--pose-log", "poses.csv",
                "--classpath", "classes");
        assertRobotDrove(run);
    }

    /** --quiet: every process the script starts (the Environment, Geometry, the robots) logs warnings and errors only. */
    @Test
    void quietLeavesTheInfoLinesOutOfEveryProcess() throws Exception {
        writeWorldAndControlClass();
        ScriptRun run = ScriptRun.of(tmp, Map.of(), tmp, REPO.resolve("scripts/headless.sh").toString(),
                "--env", "world.xml", "--steps", "20", "--pose-log", "poses.csv", "--classpath", "classes", "--quiet");
        assertRobotDrove(run);
        assertTrue(!run.stderr().contains(" INFO ") && !run.stdout().contains(" INFO "), run.stderr() + run.stdout());
        ScriptRun loud = ScriptRun.of(tmp, Map.of(), tmp, REPO.resolve("scripts/headless.sh").toString(),
                "--env", "world.xml", "--steps", "1", "--classpath", "classes", "--log-level", "loud");
        assertEquals(2, loud.exit());
        assertEquals("headless: --log-level (or ROBOSIM_LOG_LEVEL) needs one of trace, debug, info, warn, error, off, got "
                + "'loud'", loud.stderr().strip());
    }

    @Test
    void robosimClasspathReachesRobotsInOneProcess() throws Exception {
        writeWorldAndControlClass();
        ScriptRun run = ScriptRun.of(tmp, Map.of("ROBOSIM_CLASSPATH", "classes"), tmp,
                REPO.resolve("scripts/headless.sh").toString(), "--robots-in-one-process",
                "--env", "world.xml", "--no-geometry", "--steps", "20", "--pose-log", "poses.csv");
        assertRobotDrove(run);
    }

    /** SIGTERM (a kill, or Ctrl-C) on headless.sh also ends the Environment, Geometry and robot it started. */
    @Test
    void stoppingHeadlessStopsEveryProcessItStarted() throws Exception {
        writeWorldAndControlClass();
        ScriptRun run = ScriptRun.terminatedAfter("step ", tmp, Map.of(), tmp,
                REPO.resolve("scripts/headless.sh").toString(), "--env", "world.xml", "--steps", "1000000",
                "--speed", "1", "--progress", "--classpath", "classes");
        assertEquals(128 + 15, run.exit(), "ended by SIGTERM; stderr: " + run.stderr());
        assertTrue(!run.stderr().contains("did not end cleanly"), "a stop is no failure: " + run.stderr());
    }

    private void assertRobotDrove(ScriptRun run) throws IOException {
        assertEquals(0, run.exit(), "stderr: " + run.stderr());
        assertTrue(run.stdout().contains("steps=20 robots=1"), run.stdout());
        List<String> poses = Files.readAllLines(tmp.resolve("poses.csv"));
        String[] last = poses.get(poses.size() - 1).split(",");
        assertEquals("solo", last[1], poses.toString());
        assertTrue(Double.parseDouble(last[2]) > 2.5, "the robot should have moved from x = 1 m: " + poses);
    }

    private void writeWorldAndControlClass() throws IOException {
        Path src = tmp.resolve("src/scriptsit/Forward.java");
        Files.createDirectories(src.getParent());
        Files.writeString(src, """
                package scriptsit;
                public final class Forward implements robosim.api.RobotControl {
                    @Override
                    public void run(robosim.api.Robot robot) throws Exception {
                        while (true) {
                            robot.move(100);
                        }
                    }
                }
                """);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        int rc = javac.run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", tmp.resolve("classes").toString(), src.toString());
        assertEquals(0, rc, "javac of the control class");
        Files.writeString(tmp.resolve("world.xml"), """
                <?xml version="1.0" encoding="UTF-8"?>
                <environment name="scripts-it" timeStepMs="500" seed="1">
                  <arena width="6" height="6"/>
                  <robots>
                    <robot name="solo" type="Scout" control="scriptsit.Forward" x="1" y="3" heading="0"/>
                  </robots>
                </environment>
                """);
    }

    /** `git status --porcelain` of the repository (tracked changes and untracked, not ignored, files). */
    private static String gitStatus() throws Exception {
        Process git;
        try {
            git = new ProcessBuilder("git", "-C", REPO.toString(), "status", "--porcelain")
                    .redirectErrorStream(true).start();
        } catch (IOException e) {
            throw new AssertionError("ScriptsIT needs git on the PATH to see that scripts write nothing: " + e);
        }
        String out = new String(git.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, git.waitFor(), "git status in " + REPO + ": " + out);
        return out;
    }
}
