package robosim.testkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.api.Robot;
import robosim.api.RobotControl;

class SimulationTest {
    /** Drives ahead 1 m, then stands. */
    static final class AheadOneMetre implements RobotControl {
        @Override
        public void run(Robot robot) throws InterruptedException {
            robot.move(1000);
        }
    }

    @Test
    void aRobotThatDrivesAMetreIsAMetreFurtherOnAndStandsThere() {
        try (Simulation sim = Simulation.of(World.arena(4, 4).robot("r1", "Scout", 1, 2, 0))
                .control("r1", new AheadOneMetre()).start()) {
            assertEquals(new Pose(1000, 2000, 0), sim.pose("r1"));
            assertEquals(0, sim.steps());
            sim.run(40);
            assertEquals(40, sim.steps());
            assertEquals(2000, sim.pose("r1").xMm(), 1e-6);
            assertEquals(2000, sim.pose("r1").yMm(), 1e-6);
            sim.run(10);
            assertEquals(2000, sim.pose("r1").xMm(), 1e-6);
            assertTrue(sim.contacts("r1").isEmpty());
        }
    }

    @Test
    void theRunsBuiltInMetricsAreCountedAsItGoes() {
        try (Simulation sim = Simulation.of(World.arena(3, 3).robot("r1", "Scout", 1.5, 1.5, 0))
                .control("r1", new Ram()).start()) {
            assertTrue(sim.metrics().isEmpty(), "no step yet");
            assertTrue(sim.runUntil(s -> !s.contacts("r1").isEmpty(), 200), "never touched the wall");
            assertEquals((sim.pose("r1").xMm() - 1500) / 1000, sim.metric("distance_m"), 1e-9, "its path, straight");
            assertEquals(1, sim.metric("contacts"));
            assertEquals(1, sim.metric("robots_left"));
            assertEquals(robosim.environment.metrics.Metrics.names(), List.copyOf(sim.metrics().keySet()));
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.metric("speed"));
            assertTrue(e.getMessage().contains(String.join(", ", robosim.environment.metrics.Metrics.names())),
                    e.getMessage());
        }
    }

    @Test
    void runUntilStopsAtTheFirstStepTheConditionHolds() {
        try (Simulation sim = Simulation.of(World.arena(4, 4).robot("r1", "Scout", 1, 2, 0))
                .control("r1", new AheadOneMetre()).start()) {
            assertTrue(sim.runUntil(s -> s.pose("r1").xMm() >= 1500, 100));
            long at = sim.steps();
            assertTrue(at > 0 && at < 40, "at step " + at);
            assertFalse(sim.runUntil(s -> s.pose("r1").yMm() > 2500, 5));
            assertEquals(at + 5, sim.steps());
        }
    }

    /** Drives into what is ahead until it touches it. */
    static final class Ram implements RobotControl {
        @Override
        public void run(Robot robot) throws InterruptedException {
            while (robot.lastContact() == null || robot.lastContact().isEmpty()) {
                robot.move(200);
            }
        }
    }

    @Test
    void touchingAWallIsAContactAndTheSonarSawItComing() {
        try (Simulation sim = Simulation.of(World.arena(3, 3).robot("r1", "Scout", 1.5, 1.5, 0))
                .control("r1", new Ram()).start()) {
            sim.run(1);
            double[] sonar = sim.sonar("r1");
            assertEquals(16, sonar.length);
            assertTrue(sim.runUntil(s -> !s.contacts("r1").isEmpty(), 200), "never touched the wall");
            Contact c = sim.contacts("r1").get(0);
            assertNotNull(c.with());
            assertTrue(sim.pose("r1").xMm() > 2500, "at " + sim.pose("r1"));
        }
    }

    /** Says hello to everyone once, then listens. */
    static final class Greeter implements RobotControl {
        @Override
        public void run(Robot robot) throws InterruptedException {
            robot.broadcast("hello from " + robot.name());
            while (true) {
                robot.sleep(100);
            }
        }
    }

    @Test
    void aBroadcastReachesTheOtherRobots() {
        try (Simulation sim = Simulation.of(World.arena(4, 4).robot("a", "Scout", 1, 1, 0).robot("b", "ArRobot", 3, 3, 0))
                .control("a", new Greeter()).control("b", new Greeter()).start()) {
            sim.run(3);
            List<Received> atB = sim.received("b");
            assertEquals(1, atB.size(), atB.toString());
            assertEquals("a", atB.get(0).from());
            assertEquals("hello from a", atB.get(0).text());
            assertEquals("hello from b", sim.received("a").get(0).text());
        }
    }

    @Test
    void anEnvironmentFileRunsItsOwnControlClassesTheSameAsEveryTime() {
        Path maze = Path.of("..", "test-envs", "maze.xml");
        Pose first;
        try (Simulation sim = Simulation.of(maze).start()) {
            sim.run(100);
            first = sim.pose(sim.robots().get(0));
        }
        try (Simulation sim = Simulation.of(maze).start()) {
            sim.run(60).run(40);
            assertEquals(first, sim.pose(sim.robots().get(0)));
        }
    }

    /** Computes without ever calling the robot, until it is told to stop. */
    static final class Spinner implements RobotControl {
        @Override
        public void run(Robot robot) {
            while (!Thread.currentThread().isInterrupted()) {
                Thread.onSpinWait();
            }
        }
    }

    /** Its first call fails. */
    static final class Crasher implements RobotControl {
        @Override
        public void run(Robot robot) {
            throw new IllegalStateException("a bug in the control code");
        }
    }

    @Test
    void aControlThatNeverYieldsIsDroppedAfterTheStepTimeoutAndTheOthersGoOn() {
        // on JDK 21+ control code runs on virtual threads, one carrier per core: the spinning one holds one, the
        // others need another
        org.junit.jupiter.api.Assumptions.assumeTrue(Runtime.getRuntime().availableProcessors() >= 2);
        try (Simulation sim = Simulation.of(World.arena(6, 4).robot("spin", "Scout", 1, 1, 0)
                .robot("crash", "Scout", 1, 3, 0).robot("go", "Scout", 3, 2, 0))
                .control("spin", new Spinner()).control("crash", new Crasher()).control("go", new AheadOneMetre())
                .expectFailure("crash").stepTimeout(java.time.Duration.ofMillis(500)).start()) {
            sim.run(30);
            assertNotNull(sim.ended("spin"), "the spinning robot still takes part");
            assertEquals(null, sim.ended("crash"), "a control class that threw stands still, it is not dropped");
            assertTrue(sim.failed("crash") && !sim.failed("go"));
            assertEquals(0, sim.failure("crash").step());
            assertEquals(new Pose(1000, 3000, 0), sim.pose("crash"));
            assertEquals(4000, sim.pose("go").xMm(), 1e-6);
        }
    }

    /** Drives 100 mm, then has a bug. */
    static final class BugAfterAMove implements RobotControl {
        @Override
        public void run(Robot robot) throws InterruptedException {
            robot.move(100);
            String nothing = null;
            robot.report("length", nothing.length());
        }
    }

    @Test
    void controlCodeThatThrowsFailsTheTestNamingTheRobotAndTheStepWithWhatItThrewAsTheCause() {
        AssertionError failed;
        Simulation sim = Simulation.of(World.arena(4, 4).robot("a", "Scout", 1, 1, 0).robot("b", "Scout", 1, 3, 0))
                .control("a", new BugAfterAMove()).control("b", new AheadOneMetre()).start();
        try (sim) {
            failed = assertThrows(AssertionError.class, () -> sim.run(50));
            assertTrue(sim.failed("a") && !sim.failed("b"));
            long step = sim.failure("a").step();
            assertTrue(step > 0 && step < 50, "the move took some steps: " + step);
            assertTrue(failed.getMessage().startsWith("robot a: its control code failed at step " + step
                    + ": java.lang.NullPointerException"), failed.getMessage());
            assertTrue(failed.getCause() instanceof NullPointerException, String.valueOf(failed.getCause()));
            sim.run(5); // (said once: the test may go on)
        }
    }

    @Test
    void aTestThatExpectsAFailureAsksForIt() {
        try (Simulation sim = Simulation.of(World.arena(4, 4).robot("a", "Scout", 1, 1, 0))
                .control("a", new BugAfterAMove()).expectFailure("a").start()) {
            assertTrue(sim.runUntil(s -> s.failed("a"), 100));
            assertTrue(sim.failure("a").thrown() instanceof NullPointerException);
            assertEquals("a", sim.failure("a").robot());
        }
    }

    /** Reports the parameter "speed" and the seed it was given, then drives. */
    static final class SaysItsParameter implements RobotControl {
        @Override
        public void run(Robot robot) throws InterruptedException {
            robot.report("speed", robot.parameter("speed", 0.0));
            robot.report("seed", robot.seed());
            robot.move(100);
        }
    }

    @Test
    void aWorldInCodeTakesParametersAndASeedAndTheTestReadsWhatItsRobotsReported() {
        double seedOf1;
        try (Simulation sim = Simulation.of(World.arena(4, 4).robot("a", "Scout", 1, 1, 0))
                .control("a", new SaysItsParameter()).param("speed", 900).seed(1).start()) {
            assertEquals(null, sim.reported("a", "speed"), "nothing reported before the first step");
            sim.run(3);
            assertEquals(900.0, sim.reported("a", "speed"));
            assertEquals(List.of("speed", "seed"), List.copyOf(sim.reports("a").keySet()));
            seedOf1 = sim.reported("a", "seed");
        }
        try (Simulation sim = Simulation.of(World.arena(4, 4).robot("a", "Scout", 1, 1, 0))
                .control("a", new SaysItsParameter()).seed(2).start()) {
            sim.run(3);
            assertEquals(0.0, sim.reported("a", "speed"), "no parameter: the default");
            assertTrue(sim.reported("a", "seed") != seedOf1, "another run seed, another robot seed");
        }
    }

    @Test
    void anEnvironmentFileTakesItsParameterAndASeedAndItsRobotsReports() {
        Path wander = Path.of("..", "test-envs", "wander.xml");
        Pose fast;
        try (Simulation sim = Simulation.of(wander).param("speed", 900).seed(3).start()) {
            sim.run(300);
            assertNotNull(sim.reported("w1", "turns"), "w1 turned in 30 s: " + sim.reports("w1"));
            fast = sim.pose("w1");
        }
        try (Simulation sim = Simulation.of(wander).param("speed", 200).seed(3).start()) {
            sim.run(300);
            assertFalse(fast.equals(sim.pose("w1")), "another speed, another run");
        }
        IllegalArgumentException unknown = assertThrows(IllegalArgumentException.class,
                () -> Simulation.of(wander).param("sped", 900).start());
        assertTrue(unknown.getMessage().contains("sped"), unknown.getMessage());
    }

    @Test
    void aFilesPlaceholderWithoutADefaultTakesTheTestsParameter(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        Path world = dir.resolve("world.xml");
        java.nio.file.Files.writeString(world, "<environment timeStepMs=\"100\"><arena width=\"4\" height=\"4\"/><robots>"
                + "<robot name=\"a\" type=\"Scout\" x=\"${x}\" y=\"1\" heading=\"0\"/></robots></environment>");
        try (Simulation sim = Simulation.of(world).param("x", 2).control("a", new AheadOneMetre()).start()) {
            assertEquals(2000, sim.pose("a").xMm(), 1e-6);
        }
        IllegalArgumentException none = assertThrows(IllegalArgumentException.class,
                () -> Simulation.of(world).control("a", new AheadOneMetre()).start());
        assertTrue(none.getMessage().contains("x"), none.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Simulation.of(world).param("x", 2)
                .control("b", new AheadOneMetre()).start(), "a robot the file does not have");
    }

    @Test
    void whatCannotRunIsRefusedWithItsReason() {
        IllegalArgumentException noControl = assertThrows(IllegalArgumentException.class,
                () -> Simulation.of(World.arena(4, 4).robot("r1", "Scout", 1, 2, 0)).start());
        assertTrue(noControl.getMessage().contains("robot r1") && noControl.getMessage().contains("control(\"r1\""),
                noControl.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> Simulation.of(World.arena(4, 4)).control("nobody", new AheadOneMetre()));
        IllegalArgumentException badFile = assertThrows(IllegalArgumentException.class,
                () -> Simulation.of(Path.of("no-such-file.xml")));
        assertTrue(badFile.getMessage().contains("no-such-file.xml"), badFile.getMessage());
    }
}
