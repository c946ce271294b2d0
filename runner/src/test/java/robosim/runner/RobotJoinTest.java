package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.CoordinatorDesign;
import robosim.environment.run.Settings;
import robosim.examples.Wander;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.protocol.ObstacleShape;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RecordingReader;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;

/**
 * Robots joining a running world: 20 scouts join one by one during a 100-step run (at steps 4, 8, ... 80,
 * exactly: the run is held and stepped from here), each entering at the first free pose of its spawn region;
 * no robot ever overlaps another or an obstacle (JTS over the pose log), viewers get the world again with
 * each, and the same joins give the same run, pose for pose, also with a Geometry process (sent the grown
 * world each time). Bad names and full regions are refused.
 */
class RobotJoinTest {
    private static final long LONG = 60;
    private static final Path WORLD = Path.of("src/test/resources/joins.xml");
    private static final int STEPS = 100;

    /** What a recording viewer saw: the worlds (first, then one per join) and every update. */
    private record Seen(List<WorldSnapshot> worlds, List<PoseUpdate> updates, List<Integer> worldOf,
            CompletableFuture<ViewerClient> client) {
    }

    private static ClientWorkerCoordinator start() throws Exception {
        return start(true, null);
    }

    private static ClientWorkerCoordinator start(boolean inProcessGeometry, Path record) throws Exception {
        return start(Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0)
                .inProcessGeometry(inProcessGeometry).maxSteps(STEPS).resetEvery(64).record(record).build());
    }

    private static ClientWorkerCoordinator start(Settings s) throws Exception {
        ClientWorkerCoordinator env = new ClientWorkerCoordinator(new EnvironmentLoader().load(WORLD), s);
        env.startPaused();
        env.start();
        return env;
    }

    private static Seen watch(int port, PoseLog log) throws Exception {
        Seen seen = new Seen(new CopyOnWriteArrayList<>(), new CopyOnWriteArrayList<>(), new CopyOnWriteArrayList<>(),
                new CompletableFuture<>());
        ViewerClient v = ViewerClient.connect("127.0.0.1", port, true, 10_000);
        v.start(new ViewerClient.Listener() {
            @Override
            public void snapshot(WorldSnapshot snapshot) {
                seen.worlds().add(snapshot);
                log.snapshot(snapshot);
            }

            @Override
            public void update(PoseUpdate update) {
                log.update(update);
                seen.updates().add(update);
                seen.worldOf().add(seen.worlds().size() - 1);
            }
        });
        seen.client().complete(v);
        return seen;
    }

    /** A joined robot by hand: forward 100 mm every step (they press against one another and the wall). */
    private static CompletableFuture<Long> drive(RawRobot r) {
        return CompletableFuture.supplyAsync(() -> {
            try (r) {
                while (r.next()) {
                    r.step(100, 0, false, List.of());
                }
                return r.firstStep;
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
    }

    /**
     * One run: walker from the start, 20 scouts joining at steps 4, 8, ... 80; what a recording viewer saw,
     * which also wrote the pose log {@code poses}. Geometry in-process, or a Geometry process (in this JVM).
     */
    private static Seen run(boolean inProcessGeometry, Path poses, Path record) throws Exception {
        try (ClientWorkerCoordinator env = start(inProcessGeometry, record); PoseLog log = new PoseLog(poses)) {
            int[] ports = env.ports();
            if (!inProcessGeometry) {
                Socket g = new Socket(InetAddress.getLoopbackAddress(), ports[2]);
                CompletableFuture.runAsync(() -> {
                    try {
                        new robosim.geometry.GeometryClient(g, 64).run();
                    } catch (java.io.IOException e) {
                        throw new IllegalStateException(e);
                    }
                }, TestThreads.ROBOTS);
            }
            Seen seen = watch(ports[1], log);
            HardwareSimulator walker = new HardwareSimulator("walker", robosim.devices.RobotTypes.byName("ArRobot"));
            walker.connect(new Socket(InetAddress.getLoopbackAddress(), ports[0]), 64);
            CompletableFuture<String> walking = CompletableFuture.supplyAsync(() -> {
                try {
                    return walker.run(new Wander());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS);
            assertTrue(env.awaitStart(LONG, TimeUnit.SECONDS));
            List<CompletableFuture<Long>> scouts = new ArrayList<>();
            for (int k = 1; k <= 20; k++) {
                env.step(4, LONG, TimeUnit.SECONDS);
                env.pause(LONG, TimeUnit.SECONDS); // (step 4k is computed and held: the scout joins after it)
                RawRobot scout = new RawRobot("scout-" + k, robosim.devices.RobotTypes.properties("Scout"), ports[0]);
                assertTrue(scout.welcome.isAccepted(), scout.welcome.reason());
                assertEquals(1 + k, scout.welcome.robotNames().size(), "it is told every robot's name, its own last");
                scouts.add(drive(scout));
            }
            env.resume();
            assertEquals("completed " + STEPS + " steps", walking.get(LONG, TimeUnit.SECONDS));
            for (int k = 1; k <= 20; k++) {
                assertEquals(4L * k + 1, scouts.get(k - 1).get(LONG, TimeUnit.SECONDS), "scout-" + k + "'s first step");
            }
            assertTrue(env.awaitEnd(LONG, TimeUnit.SECONDS));
            seen.client().get().awaitEnd(LONG, TimeUnit.SECONDS); // (every update it was sent has been taken)
            env.awaitOutputDone(LONG * 1000); // (the recording is written)
            assertEquals(STEPS, seen.updates().size());
            return seen;
        }
    }

    @Test
    void twentyRobotsJoinOneByOneNeverOverlappingAnythingAndTheSameJoinsGiveTheSameRun(@TempDir Path dir)
            throws Exception {
        Path poses = dir.resolve("poses.csv");
        Path record = dir.resolve("joins.rec");
        Seen first = run(true, poses, record);
        assertEquals(21, first.worlds().size(), "the first world, then the world again with each scout");
        GeometryFactory jts = new GeometryFactory();
        List<Geometry> obstacles = new ArrayList<>();
        for (ObstacleShape o : first.worlds().get(0).obstacles()) {
            obstacles.add(robosim.environment.core.Obstacles.polygon(o));
        }
        for (int s = 0; s < STEPS; s++) {
            WorldSnapshot w = first.worlds().get(first.worldOf().get(s));
            assertEquals(w.robotNames().size(), first.updates().get(s).count(), "step " + s + " is of its world");
        }
        // over the pose log: every step's rows, one per robot of that step, none overlapping anything
        WorldSnapshot last = first.worlds().get(first.worlds().size() - 1);
        List<String> rows = java.nio.file.Files.readAllLines(poses);
        assertEquals("step,robot,x_m,y_m,heading_deg,state", rows.get(0));
        int row = 1;
        for (int s = 0; s < STEPS; s++) {
            List<String[]> at = new ArrayList<>();
            while (row < rows.size() && rows.get(row).startsWith((s + 1) + ",")) { // (the world after s + 1 steps)
                at.add(rows.get(row++).split(","));
            }
            assertEquals(1 + Math.min(20, s / 4), at.size(), "step " + s + ": the walker and the scouts that joined");
            for (int i = 0; i < at.size(); i++) {
                double ri = last.radiusMm(last.robotNames().indexOf(at.get(i)[1]));
                double xi = Double.parseDouble(at.get(i)[2]) * 1000;
                double yi = Double.parseDouble(at.get(i)[3]) * 1000;
                for (int j = i + 1; j < at.size(); j++) {
                    double rj = last.radiusMm(last.robotNames().indexOf(at.get(j)[1]));
                    double d = Math.hypot(xi - Double.parseDouble(at.get(j)[2]) * 1000,
                            yi - Double.parseDouble(at.get(j)[3]) * 1000);
                    assertTrue(d >= ri + rj - 1e-3, "step " + s + ": " + at.get(i)[1] + " and " + at.get(j)[1]
                            + " overlap (" + d + " mm apart)");
                }
                for (Geometry o : obstacles) {
                    assertTrue(o.distance(jts.createPoint(new Coordinate(xi, yi))) >= ri - 1e-3,
                            "step " + s + ": " + at.get(i)[1] + " overlaps an obstacle");
                }
            }
        }
        assertEquals(rows.size(), row, "nothing after the last step");
        try (RecordingReader r = new RecordingReader(record)) {
            java.io.StringWriter recorded = new java.io.StringWriter();
            try (java.io.BufferedWriter out = new java.io.BufferedWriter(recorded)) {
                RecordToolMain.poses(r, out);
            }
            assertEquals(java.nio.file.Files.readString(poses), recorded.toString(),
                    "the recording's poses (record-tool poses) are the pose log's");
            java.io.ByteArrayOutputStream summary = new java.io.ByteArrayOutputStream();
            RecordToolMain.summary(r, new java.io.PrintStream(summary, true, java.nio.charset.StandardCharsets.UTF_8));
            assertTrue(summary.toString(java.nio.charset.StandardCharsets.UTF_8).contains("joined=20 scout-1,scout-2,"),
                    summary.toString(java.nio.charset.StandardCharsets.UTF_8));
        }
        Seen second = run(false, dir.resolve("again.csv"), null); // (with a Geometry process: the world sent again)
        for (int s = 0; s < STEPS; s++) {
            PoseUpdate a = first.updates().get(s);
            PoseUpdate b = second.updates().get(s);
            assertEquals(a.count(), b.count());
            for (int i = 0; i < a.count(); i++) {
                assertEquals(a.xMm(i), b.xMm(i), "step " + s + " robot " + i);
                assertEquals(a.yMm(i), b.yMm(i), "step " + s + " robot " + i);
                assertEquals(a.headingDeg(i), b.headingDeg(i), "step " + s + " robot " + i);
            }
        }
    }

    @Test
    void aNameNoRuleAllowsAFullSpawnRegionATakenStartPoseAndADuplicateAreRefusedNamingTheValue() throws Exception {
        try (ClientWorkerCoordinator env = start()) {
            int port = env.ports()[0];
            try (RawRobot walker = new RawRobot("walker", robosim.devices.RobotTypes.properties("ArRobot"), port)) {
                assertTrue(walker.welcome.isAccepted());
                assertTrue(env.awaitStart(LONG, TimeUnit.SECONDS));
                String refused = refusal("rover", port);
                assertTrue(refused.startsWith("no robot named \"rover\" in " + WORLD + " (robots: walker; may join: "
                        + "late, scout-*, pack-?)"), refused);
                try (RawRobot pack = new RawRobot("pack-1", robosim.devices.RobotTypes.properties("Scout"), port)) {
                    assertTrue(pack.welcome.isAccepted(), pack.welcome.reason());
                    refused = refusal("pack-2", port);
                    assertTrue(refused.startsWith("the spawn region of pack-? in " + WORLD + " has no free pose for "
                            + "pack-2 (every pose in it is taken)"), refused);
                    refused = refusal("pack-1", port);
                    assertTrue(refused.startsWith("robot pack-1 is already connected"), refused);
                    try (RawRobot late = new RawRobot("late", robosim.devices.RobotTypes.properties("Scout"), port)) {
                        assertTrue(late.welcome.isAccepted(), late.welcome.reason());
                        assertEquals(10_000, late.welcome.xMm());
                        assertEquals(7_000, late.welcome.yMm());
                    }
                }
                assertFalse(env.status().robots().contains("rover"));
            }
        }
        try (ClientWorkerCoordinator env = start(Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0)
                .inProcessGeometry(true).maxSteps(STEPS).design(CoordinatorDesign.SEQUENTIAL).build());
                RawRobot walker = new RawRobot("walker", robosim.devices.RobotTypes.properties("ArRobot"), env.ports()[0])) {
            assertTrue(env.awaitStart(LONG, TimeUnit.SECONDS));
            String refused = refusal("scout-1", env.ports()[0]);
            assertTrue(refused.startsWith("robots cannot join this run: its SEQUENTIAL coordinator"), refused);
        }
    }

    private static String refusal(String name, int port) throws Exception {
        try (RawRobot r = new RawRobot(name, robosim.devices.RobotTypes.properties("Scout"), port)) {
            assertFalse(r.welcome.isAccepted(), name + " was let in");
            return r.welcome.reason();
        }
    }
}
