package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * How the headless runner ends, over real processes: a client process that ends before the start
 * stops the run at once with its reason (exit 2); a robot that is removed mid-run, by its own end or
 * by the step timeout, makes the exit code 3 and is named with its reason before the summary.
 */
class HeadlessRunnerTest {
    @Test
    void aControlClassThatIsNowhereIsOneLineAndExit2BeforeAnyProcessStarts() {
        HeadlessRun r = HeadlessRun.of("--env", "src/test/resources/unknown-control.xml", "--steps", "10");
        assertEquals(2, r.code(), r.all());
        assertEquals(List.of("src/test/resources/unknown-control.xml: <robot name=\"r1\">: control class "
                + "org.example.NoSuchControl is not on the class path (add its classes with --classpath or "
                + "ROBOSIM_CLASSPATH)"), r.err(), r.all());
    }

    @Test
    void aFileWithSeveralFaultsIsALineForEachAndExit2BeforeAnyProcessStarts() {
        String f = "src/test/resources/three-faults.xml";
        HeadlessRun r = HeadlessRun.of("--env", f, "--steps", "10");
        assertEquals(2, r.code(), r.all());
        assertEquals(3, r.err().size(), r.all());
        assertTrue(r.err().get(0).startsWith(f + ":3:1: unknown element or attribute 'colour' (known here: "), r.all());
        assertEquals(f + ":7:5: <robot name=\"r2\"> overlaps robot \"r1\"", r.err().get(1), r.all());
        assertEquals(f + ":8:5: <robot name=\"r3\"> at (20.0, 1.0) m does not fit inside the arena (radius 0.25 m)",
                r.err().get(2), r.all());
    }

    @Test
    void oneJvmWithAnOptionForRobotProcessesIsOneLineAndExit2() {
        HeadlessRun r = HeadlessRun.of("--env", "src/test/resources/three-robots.xml", "--steps", "10", "--one-jvm",
                "--robots-in-one-process");
        assertEquals(2, r.code(), r.all());
        assertEquals(List.of("headless: --one-jvm starts no robot process: --robots-in-one-process, --connection and "
                + "--exchange do not apply"), r.err(), r.all());
    }

    @Test
    void aOneJvmRunIsOneEnvironmentProcessWithEveryRobotInIt(@TempDir Path dir) throws Exception {
        Path log = dir.resolve("poses.csv");
        HeadlessRun r = HeadlessRun.of("--env", "src/test/resources/three-robots.xml", "--steps", "200", "--one-jvm",
                "--pose-log", log.toString());
        assertEquals(0, r.code(), r.all());
        String last = r.out().get(r.out().size() - 1);
        assertTrue(last.matches("steps=200 robots=3 wall_s=[0-9.]+ steps_per_s=[0-9.]+ robot_steps_per_s=[0-9.]+ .*"
                + "geometry=in-process robots_in=one-jvm"), r.all());
        List<String> rows = Files.readAllLines(log);
        assertEquals("step,robot,x_m,y_m,heading_deg,state", rows.get(0));
        assertEquals(1 + 200 * 3, rows.size(), "one row per robot per step");
        // 200 steps = 2 cycles of 88 + 24 steps forward: x = 1.5 + 24 * 0.25 m
        double[] expected = BackAndForthMath.after(199);
        assertEquals(6.0, expected[0] / 1000);
        assertEquals("200,r1,7.5,1.0,0.0,running", rows.get(rows.size() - 3), "the world after 200 steps");
        assertEquals("200,r2,7.5,2.0,0.0,running", rows.get(rows.size() - 2));
        assertEquals("200,r3,7.5,3.0,0.0,running", rows.get(rows.size() - 1));
    }

    @Test
    void aBadEnvironmentFileExits2() {
        HeadlessRun r = HeadlessRun.of("--env", "missing.xml", "--steps", "10");
        assertEquals(2, r.code());
        assertEquals(List.of("missing.xml: file not found"), r.err(), r.all());
    }

    @Test
    void controlCodeThatThrowsIsNamedBeforeTheSummaryAndTheExitCodeIs4InEveryLayout() {
        for (String[] layout : new String[][] {{"--no-geometry"}, {"--one-jvm"}}) {
            java.util.List<String> args = new java.util.ArrayList<>(List.of("--env", "src/test/resources/one-throws.xml",
                    "--steps", "20"));
            args.addAll(List.of(layout));
            HeadlessRun r = HeadlessRun.of(args.toArray(new String[0]));
            assertEquals(HeadlessRunner.EXIT_CONTROL_FAILED, r.code(), r.all());
            assertTrue(r.out().contains("robot r1: its control code failed: java.lang.IllegalStateException: a bug in "
                    + "r1's control code"), r.all());
            assertEquals(1, r.all().lines().filter(l -> l.startsWith("robot r1: its control code failed")).count(),
                    "said once: " + r.all());
            String summary = r.out().get(r.out().size() - 1);
            assertTrue(summary.startsWith("steps=20 robots=2 ") && summary.contains(" control_failed=1 "), r.all());
        }
    }

    @Test
    void aRobotProcessThatEndsBeforeTheStartEndsTheRunAtOnceWithItsReason() {
        // a JVM option the robots' JVMs refuse: they end at once, and the Environment would wait for ever
        HeadlessRun r = HeadlessRun.of("--env", "src/test/resources/one-robot.xml", "--steps", "10", "--no-geometry",
                "--robot-jvm-opts", "-XX:+NoSuchRoboSimOption");
        assertEquals(2, r.code(), r.all());
        assertTrue(r.err().stream().anyMatch(line -> Pattern.matches("headless: robot r[123] exited \\(code 1\\) "
                + "before the simulation began: .*NoSuchRoboSimOption.*; stopping everything", line)), r.all());
    }

    @Test
    void aGeometryProcessThatEndsBeforeTheStartEndsTheRunAtOnce() {
        HeadlessRun r = HeadlessRun.of("--env", "src/test/resources/one-robot.xml", "--steps", "10",
                "--geometry-jvm-opts", "-XX:+NoSuchRoboSimOption");
        assertEquals(2, r.code(), r.all());
        assertTrue(r.err().stream().anyMatch(line -> Pattern.matches("headless: geometry exited \\(code 1\\) "
                + "before the simulation began: .*NoSuchRoboSimOption.*; stopping everything", line)), r.all());
    }

    @Test
    void aRobotWhoseProcessEndsMidRunIsNamedWithItsReasonAndTheExitCodeIs3() {
        HeadlessRun r = HeadlessRun.of("--env", "src/test/resources/one-quits.xml", "--steps", "100", "--no-geometry",
                "--timeout-s", "120");
        assertEquals(HeadlessRunner.EXIT_ROBOTS_REMOVED, r.code(), r.all());
        String summary = r.summary();
        assertTrue(summary.startsWith("steps=100 robots=2 "), r.all());
        assertTrue(summary.contains(" robots_removed=1 "), r.all());
        String removed = r.out().get(r.out().size() - 2);
        java.util.regex.Matcher m = Pattern.compile("removed robot=r2 step=(\\d+) reason=.+").matcher(removed);
        assertTrue(m.matches(), r.all());
        assertTrue(Long.parseLong(m.group(1)) >= QuitsMidRun.MOVES, "it took part in its " + QuitsMidRun.MOVES
                + " steps of moving: " + removed);
    }

    @Test
    void theStepTimeoutReachesTheEnvironmentAndItsRemovalIsNamed() {
        HeadlessRun r = HeadlessRun.of("--env", "src/test/resources/one-stuck.xml", "--steps", "60", "--no-geometry",
                "--robots-in-one-process", "--step-timeout-ms", "2000", "--timeout-s", "120");
        assertEquals(HeadlessRunner.EXIT_ROBOTS_REMOVED, r.code(), r.all());
        String removed = r.out().get(r.out().size() - 2);
        assertTrue(Pattern.matches("removed robot=r2 step=\\d+ reason=sent no request for step \\d+ within 2000 ms "
                + "\\(step timeout\\): its control code made no call of the robot \\(move, turn, sleep, \\.\\.\\.\\) "
                + "since its last step, or its process stopped answering; make each pass of its loop call the robot, "
                + "robot.sleep\\(1\\) at least", removed), r.all());
    }
}
