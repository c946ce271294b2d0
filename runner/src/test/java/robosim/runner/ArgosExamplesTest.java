package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.RobotView;

/**
 * ARGoS's example experiments as examples/argos/ ports them do what they are for, each run in this JVM and read back
 * from its recording: the synchronizing foot-bots end flashing together, the gripper drags the cylinder back, and the
 * foragers bring food to the nest (their loop functions' count, in the recording and their own file), and the flock
 * aligns (its order parameter, the length of the mean heading, over 0.9) and heads for the light together, and the
 * diffusing foot-bots keep apart and keep moving (sliding along what they graze, as ARGoS's do), the lone one turns away
 * from each wall it meets, and most e-pucks keep roaming (examples/argos/README.md says what is not asserted, and why).
 */
class ArgosExamplesTest {
    @TempDir
    Path dir;

    private RecordingReader run(String world, int steps) throws Exception {
        Path record = dir.resolve(world + ".rec");
        HeadlessRun r = HeadlessRun.of("--env", Path.of("..", "examples", "argos", world).toString(), "--steps",
                Integer.toString(steps), "--one-jvm", "--record", record.toString(), "--output-dir", dir.toString(),
                "--timeout-s", "120");
        assertEquals(0, r.code(), r.all());
        assertTrue(r.summary().contains(" control_failed=0 "), r.all());
        return new RecordingReader(record);
    }

    @Test
    void theSynchronizingFootBotsEndFlashingTogether() throws Exception {
        try (RecordingReader reader = run("synchronization.xml", 3000)) {
            int lastFlash = -1;
            int together = 0;
            for (int k = 0; k < reader.steps(); k++) {
                int flashing = 0;
                for (RobotView v : reader.step(k).views()) {
                    flashing += v.reports().stream().anyMatch(r -> r.name().equals("flashing") && r.value() == 1) ? 1
                            : 0;
                }
                if (flashing > 0) {
                    lastFlash = flashing;
                    together += flashing == 16 ? 1 : 0;
                }
            }
            assertEquals(16, lastFlash, "all sixteen flash in the last flash's step");
            assertTrue(together >= 5, "five periods or more of all sixteen together: " + together);
        }
    }

    @Test
    void theGripperDragsTheCylinderBackAndLetsItGo() throws Exception {
        try (RecordingReader reader = run("gripping.xml", 200)) {
            PoseUpdate gripped = reader.step(69).update(); // (step 70: it stops and grips)
            PoseUpdate released = reader.step(119).update(); // (step 120: it lets go, then goes on back alone)
            PoseUpdate end = reader.step(199).update();
            double dragged = gripped.objectXMm(0) - released.objectXMm(0);
            assertEquals(49 * 5, dragged, 1e-6, "49 steps back at 5 cm/s with the cylinder held");
            assertEquals(released.objectXMm(0), end.objectXMm(0), 1e-9, "let go, it stays");
            assertTrue(end.xMm(0) < released.xMm(0) - 200, "the robot went on backwards without it");
        }
    }

    @Test
    void theForagersBringFoodToTheNestAndTheLoopFunctionsCountIt() throws Exception {
        try (RecordingReader reader = run("foraging.xml", 5000)) {
            java.util.Map<String, Double> metrics = robosim.sweep.RunMetrics.of(dir.resolve("foraging.xml.rec"),
                    java.util.List.of(), robosim.sweep.RunMetrics.DEFAULT_AREA_CELL_M);
            double collected = metrics.get("collected_food");
            // a walk without the state machine brings nothing back: only a forager that turns home with its item
            // and finds the nest's grey by its lights drops one
            assertTrue(collected >= 20, "items brought to the nest in 5000 steps: " + metrics);
            assertEquals(collected, metrics.get("food_items"), "each drop told to the robot that made it");
            java.util.List<String> lines = java.nio.file.Files.readAllLines(dir.resolve("foraging.txt"));
            assertEquals("# clock\twalking\tresting\tcollected_food\tenergy", lines.get(0));
            assertEquals(1 + 5000, lines.size(), "a line a step, ARGoS's columns, beside the recording");
            String[] last = lines.get(5000).split("\t");
            assertEquals("4999", last[0]);
            assertEquals(20, Integer.parseInt(last[1]) + Integer.parseInt(last[2]), "walking and resting");
            assertEquals((long) collected, Long.parseLong(last[3]));
            assertEquals(15, reader.snapshot().poses().paint().size(), "the recording opens on the fifteen items the "
                    + "loop functions' init painted on the floor");
            assertEquals(15, reader.step(0).update().paint().size(), "the fifteen items painted on the floor");
            int fewest = 15;
            for (int k = 0; k < reader.steps(); k += 100) {
                fewest = Math.min(fewest, reader.step(k).update().paint().size());
                assertTrue(reader.step(k).update().paint().size() <= 15, "never more than fifteen");
            }
            assertTrue(fewest < 15, "an item carried is off the floor");
        }
    }

    @Test
    void theFlockAlignsAndHeadsForTheLightTogether() throws Exception {
        try (RecordingReader reader = run("flocking.xml", 1500)) {
            PoseUpdate first = reader.step(0).update();
            PoseUpdate last = reader.step(1499).update();
            assertTrue(order(first) < 0.9, "headings drawn at random: " + order(first));
            int aligned = -1;
            for (int k = 0; k < reader.steps() && aligned < 0; k++) {
                aligned = order(reader.step(k).update()) > 0.9 ? k : -1;
            }
            assertTrue(aligned > 0 && aligned < 1000, "the order parameter passes 0.9 (at step " + aligned + ")");
            for (int k = 1000; k < reader.steps(); k++) {
                assertTrue(order(reader.step(k).update()) > 0.9, "and stays over it: step " + k);
            }
            double[] light = {23_900, 17_700};
            double[] from = centre(first);
            double[] to = centre(last);
            double before = Math.hypot(light[0] - from[0], light[1] - from[1]);
            double after = Math.hypot(light[0] - to[0], light[1] - to[1]);
            assertTrue(before - after > 1500, "the flock went 1.5 m or more toward the light: " + before + " to " + after);
            for (int r = 0; r < last.count(); r++) {
                assertTrue(Math.hypot(last.xMm(r) - to[0], last.yMm(r) - to[1]) < 1500, "robot " + r + " kept up");
            }
        }
    }

    /** The length of the mean of the robots' unit heading vectors: 1 when all head the same way. */
    private static double order(PoseUpdate u) {
        double x = 0;
        double y = 0;
        for (int r = 0; r < u.count(); r++) {
            x += Math.cos(Math.toRadians(u.headingDeg(r)));
            y += Math.sin(Math.toRadians(u.headingDeg(r)));
        }
        return Math.hypot(x, y) / u.count();
    }

    private static double[] centre(PoseUpdate u) {
        double x = 0;
        double y = 0;
        for (int r = 0; r < u.count(); r++) {
            x += u.xMm(r);
            y += u.yMm(r);
        }
        return new double[] {x / u.count(), y / u.count()};
    }

    @Test
    void theDiffusingFootBotsKeepApartAndKeepMoving() throws Exception {
        try (RecordingReader reader = run("diffusion_10.xml", 5000)) {
            Moves m = moves(reader, 10, "fb");
            // (a turn on one wheel beside a wall or a robot grazes it: ARGoS's robots do so too, sliding past)
            assertTrue(m.touchingRobots < m.robotSteps / 100, "robots touch each other in under 1% of their steps: "
                    + m);
            assertTrue(m.touching < m.robotSteps * 3 / 100, "anything at all in under 3%: " + m);
            for (int r = 0; r < 10; r++) {
                assertTrue(m.travelled[r] > 12_000, "robot " + r + " kept moving (25 m at most): " + m);
            }
        }
    }

    @Test
    void theLoneFootBotTurnsAwayFromEachWallItMeetsAndKeepsMoving() throws Exception {
        try (RecordingReader reader = run("diffusion_1.xml", 3000)) {
            Moves m = moves(reader, 1, "");
            // (it starts heading east and shuttles between the east and west walls: at each, it turns away on one
            // wheel, grazing the wall for about 38 steps, as ARGoS's foot-bot turns into what it sees head on)
            assertTrue(m.touches >= 4, "it met a wall again and again (7 times here): " + m);
            assertTrue(m.longestTouch < 60, "each touch ends within 6 s: " + m);
            assertTrue(m.travelled[0] > 10_000, "it kept moving (15 m at most): " + m);
        }
    }

    @Test
    void theEPucksKeepRoamingAmongTheBoxesAndCylinders() throws Exception {
        try (RecordingReader reader = run("epuck_obstacleavoidance.xml", 2000)) {
            Moves m = moves(reader, 50, "ep");
            long moving = java.util.Arrays.stream(m.travelled).filter(d -> d > 2_000).count();
            // (45 do here; e-pucks that met a corner or another e-puck head on may turn there for good:
            // examples/argos/README.md, "What differs")
            assertTrue(moving >= 40, "most travelled over 2 m of their 10 m: " + m);
        }
    }

    /**
     * What a world's robots did, step by step: their steps, those touching anything, those touching a robot, how far
     * each travelled, how many touches (a robot's steps of contact in a row) and the longest.
     */
    private record Moves(int robotSteps, int touching, int touchingRobots, double[] travelled, int touches,
            int longestTouch) {
        @Override
        public String toString() {
            return robotSteps + " robot steps, " + touching + " touching, " + touchingRobots + " touching a robot, "
                    + touches + " touches, the longest " + longestTouch + " steps, travelled (mm) " + java.util.Arrays.toString(java.util.Arrays.stream(travelled)
                    .map(Math::rint).toArray());
        }
    }

    /** {@link Moves} of {@code robots} robots, those whose names start {@code prefix} counted as robots touched. */
    private static Moves moves(RecordingReader reader, int robots, String prefix) throws Exception {
        int robotSteps = 0;
        int touchingRobots = 0;
        int touching = 0;
        double[] travelled = new double[robots];
        int[] touch = new int[robots];
        int touches = 0;
        int longestTouch = 0;
        PoseUpdate before = reader.step(0).update();
        for (int k = 1; k < reader.steps(); k++) {
            PoseUpdate now = reader.step(k).update();
            for (RobotView v : reader.step(k).views()) {
                robotSteps++;
                touching += v.contact().isEmpty() ? 0 : 1;
                boolean robot = !prefix.isEmpty() && v.contact().startsWith(prefix);
                touchingRobots += robot ? 1 : 0;
                touch[v.robot()] = v.contact().isEmpty() ? 0 : touch[v.robot()] + 1;
                touches += touch[v.robot()] == 1 ? 1 : 0;
                longestTouch = Math.max(longestTouch, touch[v.robot()]);
                travelled[v.robot()] += Math.hypot(now.xMm(v.robot()) - before.xMm(v.robot()),
                        now.yMm(v.robot()) - before.yMm(v.robot()));
            }
            before = now;
        }
        return new Moves(robotSteps, touching, touchingRobots, travelled, touches, longestTouch);
    }

    @Test
    void theLoopFunctionsKeepEachRobotsPathAndTheRecordingDrawsIt() throws Exception {
        try (RecordingReader reader = run("trajectory.xml", 2000)) {
            robosim.protocol.Traces.Log drawing = new robosim.protocol.Traces.Log();
            for (int k = 0; k < reader.steps(); k++) {
                drawing.apply(reader.step(k).update().traces());
            }
            robosim.protocol.Traces all = drawing.whole();
            PoseUpdate last = reader.step(reader.steps() - 1).update();
            List<String> names = reader.snapshot().robotNames();
            assertEquals(10, drawing.traces(), "a trace a robot");
            double[][] lastPoint = new double[10][];
            int[] points = new int[10];
            for (int p = 0; p < all.points(); p++) {
                int t = all.traceOf(p);
                int r = names.indexOf(all.name(t));
                assertTrue(r >= 0, "a robot's trace: " + all.name(t));
                if (lastPoint[r] != null) { // (ARGoS's rule: a waypoint once the robot is over 5 cm from the last)
                    double d = Math.hypot(all.xMm(p) - lastPoint[r][0], all.yMm(p) - lastPoint[r][1]);
                    assertTrue(d > 50 && d < 50 + 10, names.get(r) + "'s waypoints 5 cm apart (a step goes 5 mm at "
                            + "most): " + d);
                }
                lastPoint[r] = new double[] {all.xMm(p), all.yMm(p)};
                points[r]++;
            }
            for (int r = 0; r < 10; r++) {
                assertTrue(points[r] > 20, names.get(r) + " went its way: " + points[r] + " waypoints");
                assertTrue(Math.hypot(last.xMm(r) - lastPoint[r][0], last.yMm(r) - lastPoint[r][1]) <= 50,
                        names.get(r) + "'s path reaches where it stands");
            }
        }
    }

    @Test
    void theLoopFunctionsPlaceACluster_AScaleFreeNetworkAndALine() throws Exception {
        try (RecordingReader reader = run("custom_distributions.xml", 20)) {
            PoseUpdate u = reader.step(0).update(); // (placed before step 0; a step moves a foot-bot 10 mm at most)
            double half = Math.sqrt(Math.PI * 85.036758 * 85.036758 * 30 / 0.1) / 2 + 10;
            for (int r = 0; r < 30; r++) {
                assertTrue(Math.abs(u.xMm(r) - 20_000) <= half && Math.abs(u.yMm(r) - 15_000) <= half,
                        "fb" + r + " in the cluster's square");
            }
            assertEquals(15_000, u.xMm(30), 10, "the network's first robot at its centre");
            for (int r = 31; r < 60; r++) {
                boolean near = false;
                for (int p = 30; p < r && !near; p++) { // (its pivot: 0.75 to 1.5 m away on each axis)
                    double dx = Math.abs(u.xMm(r) - u.xMm(p));
                    double dy = Math.abs(u.yMm(r) - u.yMm(p));
                    near = dx >= 750 - 20 && dx <= 1500 + 20 && dy >= 750 - 20 && dy <= 1500 + 20;
                }
                assertTrue(near, "fb" + r + " within range of a robot placed before it");
            }
            for (int r = 60; r < 70; r++) {
                assertEquals(14_000 + (r - 60) * 1000, u.xMm(r), 10, "fb" + r + " on the line");
                assertEquals(15_000 + (r - 60) * 1000, u.yMm(r), 10);
            }
        }
    }
}
