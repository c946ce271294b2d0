package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A warm JVM's runs ({@link RunHost}, here this test JVM) against the same runs each in a fresh JVM: the same pose
 * logs, run after run, for control code and loop functions with static state ({@link CountsItsRuns}: its n-th run in
 * a JVM moves n times as far; {@link CountsItsExperiments} likewise) and for a seeded noisy world (the maze); a run of processes leaves nothing of its own running; each
 * run's class loader defines the user's classes and the examples again, RoboSim's own never.
 */
class WarmRunsTest {
    @TempDir
    Path dir;

    @Test
    void aWarmJvmsRunsAreFreshJvmsRunsAndStaticStateOfControlCodeStartsAfreshWithEachRun() throws Exception {
        Path counter = dir.resolve("counter.xml");
        Files.writeString(counter, """
                <environment name="counter" timeStepMs="100">
                  <loopFunctions class="robosim.runner.CountsItsExperiments"/>
                  <arena width="6" height="2"/>
                  <robots>
                    <robot name="c1" type="ArRobot" control="robosim.runner.CountsItsRuns" x="1" y="1"/>
                  </robots>
                </environment>
                """);
        Path maze = InJvmSimulation.env("maze.xml");
        Path classes = Path.of(CountsItsRuns.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        RunHost host = new RunHost(List.of(classes));
        List<byte[]> warm = new ArrayList<>();
        for (int k = 0; k < 2; k++) {
            warm.add(run(host, counter, "warm-counter-" + k));
            warm.add(run(host, maze, "warm-maze-" + k));
        }
        byte[] freshCounter;
        byte[] freshMaze;
        try (ChildProcesses children = new ChildProcesses(List.of("-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC"));
             HeadlessRuns fresh = HeadlessRuns.freshJvms(children)) {
            freshCounter = run(fresh, counter, "fresh-counter");
            freshMaze = run(fresh, maze, "fresh-maze");
        }
        String moved = new String(freshCounter, java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(moved.lines().anyMatch(l -> l.startsWith("19,c1,1.1,1.1,")),
                "a fresh JVM's run moves 100 mm, its loop functions 100 mm up: " + moved);
        for (int k = 0; k < 2; k++) {
            assertArrayEquals(freshCounter, warm.get(2 * k), "warm run " + (2 * k + 1) + " (the counter's)");
            assertArrayEquals(freshMaze, warm.get(2 * k + 1), "warm run " + (2 * k + 2) + " (the maze's)");
        }
    }

    private List<String> args(Path world, String name) {
        return List.of("--env", world.toString(), "--steps", "20", "--seed", "7", "--one-jvm", "--pose-log",
                dir.resolve(name + ".csv").toString(), "--timeout-s", "120");
    }

    /** The pose log of a run of {@code world} on {@code runs}, which must end cleanly. */
    private byte[] run(HeadlessRuns runs, Path world, String name) throws Exception {
        Path log = dir.resolve(name + ".log");
        HeadlessRuns.Ended ended = runs.run(name, args(world, name), log, 180);
        assertEquals(new HeadlessRuns.Ended(0, null), ended, Files.readString(log));
        return Files.readAllBytes(dir.resolve(name + ".csv"));
    }

    private byte[] run(RunHost host, Path world, String name) throws Exception {
        Path log = dir.resolve(name + ".log");
        HeadlessRuns.Ended ended = host.run(args(world, name), log);
        assertNull(ended.broke(), Files.readString(log));
        assertEquals(0, ended.code(), Files.readString(log));
        return Files.readAllBytes(dir.resolve(name + ".csv"));
    }

    @Test
    void aRunOfProcessesLeavesNothingRunningInAWarmJvm() throws Exception {
        // (the JDK's own threads such a run starts, the process reaper on JDK 17, are not the run's)
        RunHost host = new RunHost(List.of());
        Path log = dir.resolve("processes.log");
        HeadlessRuns.Ended ended = host.run(List.of("--env", "src/test/resources/one-robot.xml", "--steps", "5",
                "--timeout-s", "120"), log);
        assertEquals(new HeadlessRuns.Ended(0, null), ended, Files.readString(log));
    }

    @Test
    void eachRunsLoaderDefinesTheUsersClassesAndTheExamplesAfreshButNeverRoboSimsOwn() throws Exception {
        Path classes = Path.of(CountsItsRuns.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Path api = Path.of(robosim.api.RobotControl.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        ClassLoader parent = WarmRunsTest.class.getClassLoader();
        try (ControlClassLoader first = new ControlClassLoader("run", List.of(api, classes), parent);
             ControlClassLoader second = new ControlClassLoader("run", List.of(api, classes), parent)) {
            // the user's path holds RoboSim's robot API too: it is still RoboSim's, once for all runs
            assertSame(robosim.api.RobotControl.class, first.loadClass("robosim.api.RobotControl"));
            for (String name : List.of(CountsItsRuns.class.getName(), "robosim.examples.Wander")) {
                Class<?> one = first.loadClass(name);
                assertSame(first, one.getClassLoader(), name);
                assertNotSame(one, second.loadClass(name), name + " is defined again for each run");
                assertTrue(robosim.api.RobotControl.class.isAssignableFrom(one), name);
            }
        }
    }
}
