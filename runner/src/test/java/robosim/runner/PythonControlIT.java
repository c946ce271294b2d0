package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Control code in Python ({@code control="python:..."}, the package in {@code python/}), run by
 * {@code scripts/headless.sh} as a user runs it, in one JVM (a layout's pose logs are every layout's:
 * {@code SameRunEveryLayoutTest}): the same robot written in Java and in Python moves the same, and a
 * Python controller that fails is a failed control code as a Java one is. Runs after package (failsafe), when
 * runner/target/lib holds the built jars; the Python is {@link PythonForTests}'s.
 */
class PythonControlIT {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();
    private static final String STEPS = "300";

    @TempDir
    Path dir;

    @Test
    void theSameRobotInJavaAndInPythonGivesAByteIdenticalPoseLog() throws Exception {
        Path python = dir.resolve("python.csv");
        Path java = dir.resolve("java.csv");
        ScriptRun py = headless("--one-jvm", "--env", "examples/python/bounce.xml", "--steps", STEPS, "--pose-log",
                python.toString());
        ScriptRun jv = headless("--one-jvm", "--env", "examples/python/bounce.xml", "--steps", STEPS, "--param",
                "control=robosim.examples.Bounce", "--pose-log", java.toString());
        assertEquals(0, py.exit(), py.stdout() + py.stderr());
        assertEquals(0, jv.exit(), jv.stdout() + jv.stderr());
        assertTrue(py.stdout().contains("steps=" + STEPS + " robots=4 ") && py.stdout().contains(" control_failed=0 "),
                py.stdout());
        String poses = Files.readString(python);
        assertEquals(Files.readString(java), poses, "the Python robots moved otherwise than the Java ones");
        assertEquals(4 * Integer.parseInt(STEPS) + 1, poses.lines().count(), "a pose a robot a step, and a header");
        Matcher turned = Pattern.compile("(?m)^" + STEPS + ",b1,[^,]+,[^,]+,([^,]+),").matcher(poses);
        assertTrue(turned.find() && Double.parseDouble(turned.group(1)) != 0.0,
                "b1 bounced off something (its heading changed): " + poses.lines().skip(poses.lines().count() - 4)
                        .toList());
    }

    @Test
    void theForagingFootBotInJavaAndInPythonGivesAByteIdenticalPoseLogAndCarriesCans() throws Exception {
        // the proximity, light and ground readings, the wheels, the LEDs and the gripper through both languages
        String steps = "900";
        Path python = dir.resolve("python.csv");
        Path java = dir.resolve("java.csv");
        Path record = dir.resolve("java.rec");
        ScriptRun py = headless("--one-jvm", "--env", "test-envs/foraging.xml", "--steps", steps, "--param",
                "control=python:../examples/python/forage.py", "--pose-log", python.toString());
        ScriptRun jv = headless("--one-jvm", "--env", "test-envs/foraging.xml", "--steps", steps, "--pose-log",
                java.toString(), "--record", record.toString());
        assertEquals(0, py.exit(), py.stdout() + py.stderr());
        assertEquals(0, jv.exit(), jv.stdout() + jv.stderr());
        assertTrue(py.stdout().contains(" control_failed=0 "), py.stdout());
        assertEquals(Files.readString(java), Files.readString(python), "the Python foot-bots moved otherwise");
        ScriptRun reports = ScriptRun.of(REPO, Map.of(), dir, "bash", "scripts/record-tool.sh", "reports",
                record.toString());
        assertTrue(reports.stdout().contains(",delivered,"), "a can was carried to the nest: " + reports.stdout());
    }

    @Test
    void argosForagersAndFlockInJavaAndInPythonGiveByteIdenticalPoseLogs() throws Exception {
        // ARGoS's footbot_foraging (its chances a SplittableRandom of the robot's seed; the loop functions' messages)
        // and footbot_flocking (the camera's blobs; sines and cosines): robosim.portable in both languages
        for (String world : new String[] {"foraging", "flocking"}) {
            String steps = world.equals("foraging") ? "600" : "400";
            Path python = dir.resolve(world + "-python.csv");
            Path java = dir.resolve(world + "-java.csv");
            ScriptRun py = headless("--one-jvm", "--env", "examples/argos/" + world + ".xml", "--steps", steps,
                    "--param", "control=python:../python/argos_" + world + ".py", "--pose-log", python.toString(),
                    "--output-dir", dir.resolve("python").toString());
            ScriptRun jv = headless("--one-jvm", "--env", "examples/argos/" + world + ".xml", "--steps", steps,
                    "--pose-log", java.toString(), "--output-dir", dir.resolve("java").toString());
            assertEquals(0, py.exit(), py.stdout() + py.stderr());
            assertEquals(0, jv.exit(), jv.stdout() + jv.stderr());
            assertTrue(py.stdout().contains(" control_failed=0 "), py.stdout());
            assertEquals(Files.readString(java), Files.readString(python), "the Python " + world + " moved otherwise");
        }
        java.util.List<String> food = Files.readAllLines(dir.resolve("python").resolve("foraging.txt"));
        assertEquals(food.get(food.size() - 1), Files.readAllLines(dir.resolve("java").resolve("foraging.txt"))
                .get(food.size() - 1), "the same food brought home, the same energy");
        assertTrue(Integer.parseInt(food.get(food.size() - 1).split("\t")[3]) > 0, "food was brought home: "
                + food.get(food.size() - 1));
        // ARGoS's foraging loop functions in Python (the loop link), beside the Java robots: the same world
        Path loop = dir.resolve("foraging-loop.csv");
        ScriptRun lp = headless("--one-jvm", "--env", "examples/argos/foraging.xml", "--steps", "600", "--param",
                "loop=python:../python/argos_foraging_loop.py", "--pose-log", loop.toString(), "--output-dir",
                dir.resolve("loop").toString());
        assertEquals(0, lp.exit(), lp.stdout() + lp.stderr());
        assertEquals(Files.readString(dir.resolve("foraging-java.csv")), Files.readString(loop),
                "the Python loop functions' world moved otherwise");
        assertEquals(Files.readString(dir.resolve("java").resolve("foraging.txt")),
                Files.readString(dir.resolve("loop").resolve("foraging.txt")), "their file is the Java class's");
    }

    @Test
    void pythonLoopFunctionsChangeTheWorldAndTheirFailuresEndTheRunWithOneLine() throws Exception {
        Files.writeString(dir.resolve("every.py"), """
                from robosim.loop import Experiment, ExperimentValueError, LoopFunctions

                class Every(LoopFunctions):
                    def init(self, world: Experiment) -> None:
                        assert world.parameter("gain", 1.0) == 2.5 and world.parameter("name", "x") == "g"
                        assert world.robots == 2 and world.robot_name(1) == "r2" and world.lights == 1
                        world.paint_disc(1000, 1000, 200, 0xFF0000)
                        assert world.floor_colour(1000, 1000) == 0xFF0000
                        world.switch_light(0, False)
                        assert not world.light_on(0)
                        assert world.move_robot(1, 1500, 1500, 450)
                        assert world.robot_x_mm(1) == 1500 and world.robot_heading_deg(1) == 90
                        assert not world.move_robot(1, 500, 500, 0), "onto r1"
                        for bad in (lambda: world.report("not a name!", 1), lambda: world.switch_light(-1, True),
                                    lambda: world.paint_disc(0, 0, 10, 0x1000000), lambda: world.tell(9, "x")):
                            try:
                                bad()
                                raise AssertionError("a bad value taken")
                            except ExperimentValueError:
                                pass

                    def post_step(self, world: Experiment) -> None:
                        world.report("seen", world.step)
                        world.tell(0, "hello")
                        world.trace("r1", world.robot_x_mm(0), world.robot_y_mm(0), 0x00FF00)
                        if world.step == 5:
                            world.erase_traces()

                    def finished(self, world: Experiment) -> bool:
                        return world.step == 7

                loop_functions = Every
                """);
        Files.writeString(dir.resolve("raises.py"), """
                from robosim.loop import LoopFunctions

                class Raises(LoopFunctions):
                    def pre_step(self, world):
                        if world.step == 3:
                            print("about to divide")
                            1 / 0

                    def destroy(self, world):
                        print("destroyed after the failure")

                loop_functions = Raises
                """);
        Files.writeString(dir.resolve("syntax.py"), "def oops(:\n    pass\n");
        Files.writeString(dir.resolve("badcall.py"), """
                from robosim.loop import LoopFunctions

                class BadCall(LoopFunctions):
                    def init(self, world):
                        world._request("launch_missiles", 1)

                loop_functions = BadCall
                """);
        Files.writeString(dir.resolve("garbage.py"), """
                from robosim.loop import LoopFunctions

                class Garbage(LoopFunctions):
                    def init(self, world):
                        world._frames.send_packed(bytes([0, 0, 0, 1, 0xC1]))  # (a byte MessagePack never uses)
                        world._frames.receive()

                loop_functions = Garbage
                """);
        Files.writeString(dir.resolve("quits.py"), """
                import os
                from robosim.loop import LoopFunctions

                class Quits(LoopFunctions):
                    def pre_step(self, world):
                        if world.step == 2:
                            os._exit(3)

                loop_functions = Quits
                """);
        Path world = Files.writeString(dir.resolve("loop.xml"), """
                <environment name="loop" timeStepMs="100" seed="1">
                  <loopFunctions class="python:${script}">
                    <param name="gain" value="2.5"/>
                    <param name="name" value="g"/>
                  </loopFunctions>
                  <arena width="3" height="3"/>
                  <lights><light name="l" x="2" y="2" height="0.5"/></lights>
                  <robots>
                    <robot name="r1" type="foot-bot" control="robosim.examples.Diffusion" x="0.5" y="0.5" heading="0"/>
                    <robot name="r2" type="foot-bot" control="robosim.examples.Diffusion" x="2.5" y="2.5" heading="0"/>
                  </robots>
                </environment>
                """);
        ScriptRun every = headless("--one-jvm", "--env", world.toString(), "--steps", "100", "--param",
                "script=every.py", "--record", dir.resolve("every.rec").toString());
        assertEquals(0, every.exit(), every.stdout() + every.stderr());
        assertTrue(every.stdout().contains("steps=7 robots=2 "), "finished after step 7: " + every.stdout());
        ScriptRun reports = ScriptRun.of(REPO, Map.of(), dir, "bash", "scripts/record-tool.sh", "reports",
                dir.resolve("every.rec").toString());
        assertTrue(reports.stdout().contains("7,loop,seen,7"), reports.stdout());
        robosim.protocol.Traces.Log drawn = new robosim.protocol.Traces.Log();
        try (robosim.protocol.RecordingReader r = new robosim.protocol.RecordingReader(dir.resolve("every.rec"))) {
            for (int k = 0; k < r.steps(); k++) {
                drawn.apply(r.step(k).update().traces());
            }
        }
        robosim.protocol.Traces whole = drawn.whole(); // (a point each post-step, erased at step 5: steps 6 and 7's)
        assertEquals(2, whole.points(), "drawn, erased and drawn on");
        assertEquals("r1", whole.name(0));
        assertEquals(0x00FF00, whole.rgb(0));

        ScriptRun raises = headless("--one-jvm", "--env", world.toString(), "--steps", "100", "--param",
                "script=raises.py");
        assertEquals(4, raises.exit(), raises.stdout() + raises.stderr());
        assertTrue(raises.stderr().contains("loop functions python:" + dir.resolve("raises.py") + " failed in preStep"
                + " at step 3: ZeroDivisionError: division by zero\n"), raises.stderr());
        assertTrue(raises.stderr().contains("loop: about to divide"), "its output logged: " + raises.stderr());
        assertTrue(raises.stderr().contains("loop: destroyed after the failure"), "destroy called: " + raises.stderr());
        assertEquals(1, raises.stderr().split("Traceback \\(most recent call last\\)", -1).length - 1,
                "the traceback once: " + raises.stderr());

        ScriptRun syntax = headless("--one-jvm", "--env", world.toString(), "--steps", "100", "--param",
                "script=syntax.py");
        assertEquals(2, syntax.exit(), syntax.stdout() + syntax.stderr()); // (compiled before the run: none starts)
        assertTrue(syntax.stderr().strip().startsWith(dir.resolve("syntax.py") + ":1: SyntaxError: "), syntax.stderr());
        assertEquals("", syntax.stdout());

        ScriptRun bad = headless("--one-jvm", "--env", world.toString(), "--steps", "100", "--param",
                "script=badcall.py");
        assertEquals(4, bad.exit(), bad.stdout() + bad.stderr());
        assertTrue(bad.stderr().contains("failed in init at step 0: its script badcall.py made a bad call: no request "
                + "launch_missiles"), bad.stderr());

        ScriptRun garbage = headless("--one-jvm", "--env", world.toString(), "--steps", "100", "--param",
                "script=garbage.py");
        assertEquals(4, garbage.exit(), garbage.stdout() + garbage.stderr());
        assertTrue(garbage.stderr().contains("failed in init at step 0: its script garbage.py made a bad call: a frame "
                + "that is not MessagePack"), garbage.stderr());

        ScriptRun quits = headless("--one-jvm", "--env", world.toString(), "--steps", "100", "--param",
                "script=quits.py");
        assertEquals(4, quits.exit(), quits.stdout() + quits.stderr());
        assertTrue(Pattern.compile("failed in preStep at step 2: its script quits.py (exited \\(exit code 3\\)|ended "
                + "the link) in pre_step").matcher(quits.stderr()).find(), quits.stderr());
    }

    @Test
    void aPythonControllerThatRaisesOrExitsIsAFailedControlCodeAndTheWorldGoesOn() throws Exception {
        Files.writeString(dir.resolve("raises.py"), """
                def control(robot):
                    robot.move(250)
                    print("about to divide")
                    return 1 / 0
                """);
        Files.writeString(dir.resolve("exits.py"), """
                import os

                def control(robot):
                    robot.move(250)
                    os._exit(3)
                """);
        Path world = Files.writeString(dir.resolve("failing.xml"), """
                <environment name="failing" timeStepMs="100" seed="1">
                  <arena width="6" height="6"/>
                  <robots>
                    <robot name="raiser" type="Scout" control="python:raises.py" x="1" y="1" heading="0"/>
                    <robot name="quitter" type="Scout" control="python:exits.py" x="3" y="1" heading="0"/>
                    <robot name="goer" type="Scout" control="python:%s" x="1" y="4" heading="0"/>
                  </robots>
                </environment>
                """.formatted(REPO.resolve("examples/python/bounce.py")));
        ScriptRun run = headless("--one-jvm", "--env", world.toString(), "--steps", "100");
        String all = run.stdout() + run.stderr();
        assertEquals(4, run.exit(), all);
        assertTrue(run.stdout().contains("robot raiser: its control code failed: ZeroDivisionError: division by zero\n"),
                run.stdout());
        // (its exit code said once the exit is seen, within 5 s; the link's end is said either way)
        assertTrue(Pattern.compile("robot quitter: its control code failed: its script exits.py (exited \\(exit code 3\\)"
                + "|ended the link): the controller closed the link without a bye").matcher(run.stdout()).find(),
                run.stdout());
        assertTrue(run.stdout().contains("steps=100 robots=3 ") && run.stdout().contains(" control_failed=2 "),
                run.stdout());
        assertEquals(1, all.split("Traceback \\(most recent call last\\)", -1).length - 1, "the traceback once: " + all);
        assertTrue(run.stderr().contains("raiser: its controller failed:\nraiser| Traceback (most recent call last):\n"
                + "raiser|   File \"" + dir.resolve("raises.py") + "\", line 4, in control"), run.stderr());
        assertTrue(run.stderr().contains("raiser: about to divide"), "its output logged: " + run.stderr());
    }

    @Test
    void aScriptThatDoesNotCompileIsOneLineBeforeAnythingRuns() throws Exception {
        Files.writeString(dir.resolve("typo.py"), """
                def control(robot):
                    while True
                        robot.move(250)
                """);
        Path world = Files.writeString(dir.resolve("typo.xml"), """
                <environment name="typo" timeStepMs="100" seed="1">
                  <arena width="6" height="6"/>
                  <robots>
                    <robot name="r1" type="Scout" control="python:typo.py" x="1" y="1" heading="0"/>
                    <robot name="r2" type="Scout" control="python:typo.py" x="3" y="1" heading="0"/>
                  </robots>
                </environment>
                """);
        ScriptRun run = headless("--one-jvm", "--env", world.toString(), "--steps", "100");
        assertEquals(2, run.exit(), run.stdout() + run.stderr());
        assertEquals(dir.resolve("typo.py") + ":2: SyntaxError: expected ':'", run.stderr().strip(),
                "one line, the file and the line first; nothing else");
        assertEquals("", run.stdout(), "no run started");
    }

    @Test
    void aParameterAskedForAndNotGivenAndOneGivenAndNotAskedForAreWarnedOnceAtTheEnd() throws Exception {
        Files.writeString(dir.resolve("asks.py"), """
                def control(robot):
                    robot.set_velocity(robot.parameter("sped", 300.0))
                    while True:
                        robot.move(250)
                """);
        Path world = Files.writeString(dir.resolve("asks.xml"), """
                <environment name="asks" timeStepMs="100" seed="1">
                  <param name="speed" value="400"/>
                  <arena width="6" height="6"/>
                  <robots>
                    <robot name="r1" type="Scout" control="python:asks.py" x="1" y="1" heading="0"/>
                    <robot name="r2" type="Scout" control="python:asks.py" x="1" y="3" heading="0"/>
                  </robots>
                </environment>
                """);
        ScriptRun run = headless("--one-jvm", "--env", world.toString(), "--steps", "20");
        assertEquals(0, run.exit(), run.stdout() + run.stderr());
        String warned = "parameter \"sped\" asked for by the control code of r1, r2 is not given to them (its default"
                + " was used); given: speed";
        assertEquals(1, run.stderr().split(Pattern.quote(warned), -1).length - 1, run.stderr());
        assertTrue(run.stderr().contains("parameter \"speed\" of the world was asked for by no robot's control code; "
                + "asked: sped"), run.stderr());
    }

    private ScriptRun headless(String... args) throws Exception {
        String[] cmd = new String[args.length + 2];
        cmd[0] = "bash";
        cmd[1] = "scripts/headless.sh";
        System.arraycopy(args, 0, cmd, 2, args.length);
        Map<String, String> env = PythonForTests.environment();
        return ScriptRun.of(REPO, env, dir, cmd);
    }
}
