package robosim.testkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.api.RobotControl;
import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;

/**
 * A world's loop functions in a whole simulation: called in order (init before step 0, then each step's pre-step and
 * post-step, with the steps completed), seeing the world as the step left it, and changing it so that the robots
 * sense the change at their next step: paint under a foot-bot turns its ground sensors black, a light switched off
 * leaves its light sensors dark, a message reaches it from {@code loop}, an object and the robot itself are moved
 * (and refused where they would overlap). Ending the run and throwing end it, with the reason.
 */
class LoopFunctionsTest {
    private static final String WORLD = """
            <environment name="probe" timeStepMs="100" seed="5">
              <loopFunctions class="robosim.testkit.LoopFunctionsTest$Probe">
                <param name="greeting" value="hi"/>
              </loopFunctions>
              <arena width="3" height="2"/>
              <floor colour="white"/>
              <lights>
                <light name="lamp" x="1.5" y="1" height="0.5" intensity="3" colour="yellow"/>
              </lights>
              <objects>
                <box name="crate" x="2.5" y="0.5" width="0.2" depth="0.2" height="0.1"/>
              </objects>
              <robots>
                <robot name="fb" type="foot-bot" x="1" y="1" heading="0" devices="ground light"/>
              </robots>
            </environment>
            """;

    @TempDir
    Path dir;

    /** Loop functions that log each call, run what the test planned for a step's pre-step, and finish at a step. */
    public static final class Probe implements LoopFunctions {
        final List<String> calls = new ArrayList<>();
        final java.util.Map<Long, Consumer<Experiment>> plan = new java.util.HashMap<>();
        long finishAt = -1;
        String greeting;
        int destroyed;

        @Override
        public void init(Experiment world) {
            calls.add("init " + world.step());
            greeting = world.parameter("greeting", "none");
        }

        @Override
        public void preStep(Experiment world) {
            calls.add("pre " + world.step());
            Consumer<Experiment> c = plan.get(world.step());
            if (c != null) {
                c.accept(world);
            }
        }

        @Override
        public void postStep(Experiment world) {
            calls.add("post " + world.step());
        }

        @Override
        public boolean finished(Experiment world) {
            return world.step() == finishAt;
        }

        @Override
        public void destroy(Experiment world) {
            destroyed++;
        }
    }

    /** The foot-bot stands still and keeps its readings after each step (the first after step 0 at index 0). */
    private static final class Reads implements RobotControl {
        final List<Double> ground = new java.util.concurrent.CopyOnWriteArrayList<>();
        final List<Double> light = new java.util.concurrent.CopyOnWriteArrayList<>();

        @Override
        public void run(robosim.api.Robot robot) throws InterruptedException {
            while (true) {
                robot.step();
                ground.add(robot.sensor("ground")[0]);
                light.add(java.util.Arrays.stream(robot.sensor("light")).sum());
            }
        }
    }

    private Path world() throws Exception {
        Path file = dir.resolve("probe.xml");
        Files.writeString(file, WORLD);
        return file;
    }

    @Test
    void theLoopFunctionsAreCalledInOrderAndWhatTheyChangeTheRobotSensesAtItsNextStep() throws Exception {
        Probe probe = new Probe();
        boolean[] moves = new boolean[3];
        double[] crate = new double[2];
        probe.plan.put(3L, w -> {
            w.paintDisc(w.robotXMm(0), w.robotYMm(0), 200, 0x000000);
            w.switchLight(0, false);
            w.tell(0, "hello");
            moves[0] = w.moveObject(0, 1000, 1000, 0); // (onto the robot: refused)
            moves[1] = w.moveObject(0, 2000, 1500, 45);
        });
        probe.plan.put(6L, w -> {
            crate[0] = w.objectXMm(0);
            crate[1] = w.objectHeadingDeg(0);
            w.erasePaint();
            w.switchLight(0, true);
            moves[2] = w.moveRobot(0, 500, 500, 90);
        });
        probe.finishAt = 9;
        Reads reads = new Reads();
        try (Simulation sim = Simulation.of(world()).control("fb", reads).loopFunctions(probe).start()) {
            IllegalStateException ended = assertThrows(IllegalStateException.class, () -> sim.run(20));
            assertTrue(ended.getMessage().contains("ended after 9 steps: the experiment is finished "
                    + "(robosim.testkit.LoopFunctionsTest$Probe) after 9 steps"), ended.getMessage());
            assertEquals(List.of(new Received(3, "loop", "hello")), sim.received("fb"));
            assertEquals(500, sim.pose("fb").xMm(), 1e-9, "moved by the loop functions");
            assertEquals(90, sim.pose("fb").headingDeg(), 1e-9);
        }
        List<String> calls = new ArrayList<>(List.of("init 0"));
        for (int k = 0; k < 9; k++) {
            calls.add("pre " + k);
            calls.add("post " + (k + 1));
        }
        assertEquals(calls, probe.calls);
        assertEquals(1, probe.destroyed, "destroyed once, at the end");
        assertEquals("hi", probe.greeting, "the <loopFunctions> parameter");
        assertEquals(List.of(1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0), reads.ground.subList(0, 7),
                "white, painted black under it in step 3, erased in step 6");
        for (int k = 0; k < 7; k++) {
            assertEquals(k < 3 || k > 5, reads.light.get(k) > 0, "the lamp ahead, off in steps 3 to 5: " + reads.light);
        }
        assertFalse(moves[0], "an object onto a robot is refused");
        assertTrue(moves[1], "an object moved to a free place");
        assertEquals(2000, crate[0], 1e-9);
        assertEquals(45, crate[1], 1e-9);
        assertTrue(moves[2], "the robot moved to a free place");
    }

    @Test
    void anObjectTakenOutOfTheWorldIsNotMetAndOneAddedBackIs() throws Exception {
        Probe probe = new Probe();
        boolean[] refused = new boolean[3];
        probe.plan.put(0L, w -> { // (the crate right ahead of the foot-bot, then out of the world)
            w.moveObject(0, 1300, 1000, 0);
            w.removeObject(0);
            refused[0] = !w.objectPresent(0);
            try {
                w.moveObject(0, 2000, 1000, 0);
            } catch (IllegalStateException e) {
                refused[1] = true;
            }
        });
        probe.plan.put(60L, w -> { // (back, onto the foot-bot: refused; then ahead of it)
            refused[2] = !w.addObject(0, w.robotXMm(0), w.robotYMm(0), 0);
            w.addObject(0, w.robotXMm(0) + 300, 1000, 0);
        });
        RobotControl ahead = robot -> {
            robot.setWheelSpeeds(100, 100);
            while (true) {
                robot.step();
            }
        };
        try (Simulation sim = Simulation.of(world()).control("fb", ahead).loopFunctions(probe).start()) {
            sim.run(60);
            assertTrue(sim.pose("fb").xMm() > 1500, "through where the crate was: " + sim.pose("fb"));
            assertEquals(List.of(), sim.contacts("fb"), "nothing met");
            sim.run(60);
            assertEquals("crate", sim.contacts("fb").get(0).with(), "the crate again, back in the world");
        }
        assertTrue(refused[0] && refused[1] && refused[2], java.util.Arrays.toString(refused));
    }

    @Test
    void loopFunctionsThatThrowEndTheRunNamingThemTheCallAndTheStep() throws Exception {
        Probe probe = new Probe();
        probe.plan.put(3L, w -> {
            throw new IllegalStateException("no food left");
        });
        try (Simulation sim = Simulation.of(world()).control("fb", new Reads()).loopFunctions(probe).start()) {
            IllegalStateException ended = assertThrows(IllegalStateException.class, () -> sim.run(10));
            assertTrue(ended.getMessage().endsWith("ended after 3 steps: loop functions "
                    + "robosim.testkit.LoopFunctionsTest$Probe failed in preStep at step 3: "
                    + "java.lang.IllegalStateException: no food left"), ended.getMessage());
        }
        assertEquals(1, probe.destroyed, "destroyed once all the same: its files closed");
    }

    @Test
    void aWorldWithLoopFunctionsHasNoRobotNamedLoop() throws Exception {
        Path file = dir.resolve("named-loop.xml");
        Files.writeString(file, WORLD.replace("name=\"fb\"", "name=\"loop\""));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Simulation.of(file).control("loop", new Reads()).start());
        assertTrue(e.getMessage().contains("<loopFunctions>: a robot is named \"loop\""), e.getMessage());
    }
}
