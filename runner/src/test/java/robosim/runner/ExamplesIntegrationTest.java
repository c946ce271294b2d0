package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.api.RobotControl;
import robosim.environment.core.WorldSpec;
import robosim.examples.FollowTheLeader;
import robosim.examples.RemoteControlRobot;
import robosim.examples.TagChase;
import robosim.examples.Wander;
import robosim.protocol.ObstacleShape;
import robosim.protocol.PoseUpdate;

/** The example control programs in their environments, over real sockets with a Geometry client. */
class ExamplesIntegrationTest {
    private static double radius(WorldSpec.RobotSpec r) {
        return robosim.devices.RobotTypes.properties(r.type()).radiusMm();
    }

    /**
     * 1500 steps: each robot wanders some 275 to 295 m in them (past the 200 m asked by about step 1100), running
     * into the maze's walls and each other many times over.
     */
    @Test
    void wanderRobotsInTheMazeNeverOverlapAWallOrEachOther() throws Exception {
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("maze.xml")).run(1500, false, Wander::new);
        GeometryFactory gf = new GeometryFactory();
        List<Geometry> walls = new ArrayList<>();
        for (ObstacleShape o : sim.spec.obstacles()) {
            Coordinate[] ring = new Coordinate[o.vertexCount() + 1];
            for (int v = 0; v < o.vertexCount(); v++) {
                ring[v] = new Coordinate(o.x(v), o.y(v));
            }
            ring[o.vertexCount()] = ring[0];
            walls.add(gf.createPolygon(ring));
        }
        List<WorldSpec.RobotSpec> robots = sim.spec.robots();
        double[] travelled = new double[robots.size()];
        PoseUpdate previous = null;
        assertEquals(1500, sim.updates.size());
        for (PoseUpdate u : sim.updates) {
            for (int i = 0; i < robots.size(); i++) {
                double r = radius(robots.get(i));
                double x = u.xMm(i);
                double y = u.yMm(i);
                assertTrue(x >= r - 1e-6 && x <= 12_000 - r + 1e-6 && y >= r - 1e-6 && y <= 12_000 - r + 1e-6,
                        robots.get(i).name() + " left the arena at step " + u.step());
                for (Geometry w : walls) {
                    assertTrue(w.distance(gf.createPoint(new Coordinate(x, y))) >= r - 1e-6,
                            robots.get(i).name() + " overlaps a wall at step " + u.step());
                }
                for (int j = i + 1; j < robots.size(); j++) {
                    assertTrue(Math.hypot(x - u.xMm(j), y - u.yMm(j)) >= r + radius(robots.get(j)) - 1e-6,
                            robots.get(i).name() + " overlaps " + robots.get(j).name() + " at step " + u.step());
                }
                if (previous != null) {
                    travelled[i] += Math.hypot(x - previous.xMm(i), y - previous.yMm(i));
                }
            }
            previous = u;
        }
        for (int i = 0; i < robots.size(); i++) {
            assertTrue(travelled[i] > 200_000, robots.get(i).name() + " wandered only " + travelled[i] + " mm");
        }
    }

    @Test
    void followersEndNearTheLeader() throws Exception {
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("follow.xml"))
                .run(3000, false, FollowTheLeader::new);
        PoseUpdate last = sim.updates.get(sim.updates.size() - 1);
        PoseUpdate first = sim.updates.get(0);
        assertTrue(Math.hypot(last.xMm(0) - first.xMm(0), last.yMm(0) - first.yMm(0)) > 2000, "the leader moved");
        for (int i = 1; i < last.count(); i++) {
            double d = Math.hypot(last.xMm(i) - last.xMm(0), last.yMm(i) - last.yMm(0));
            assertTrue(d < 3000, sim.spec.robots().get(i).name() + " ended " + d + " mm from the leader");
        }
    }

    /** 500 steps: the chaser has tagged all three others by step 250. */
    @Test
    void theChaserTagsTheOthers() throws Exception {
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("tag.xml")).run(500, false, TagChase::new);
        List<String> tags = sim.updates.get(sim.updates.size() - 1).tags();
        assertFalse(tags.isEmpty(), "nobody was tagged");
        for (String t : tags) {
            assertTrue(t.startsWith("chaser>r"), t);
        }
    }

    @Test
    void aRemoteControlRobotDoesWhatItIsTold() throws Exception {
        List<String> replies = new ArrayList<>();
        int[] made = {0};
        InJvmSimulation sim = new InJvmSimulation(Path.of("src/test/resources/rc.xml")).run(12, true, () ->
                made[0]++ == 0 ? (RobotControl) robot -> drive(robot, replies) : new RemoteControlRobot());
        // forward 500 (2 steps), left 90 (1 step), forward 250 (1 step) and nothing for "jump"
        PoseUpdate last = sim.updates.get(sim.updates.size() - 1);
        assertEquals(1000 + 500, last.xMm(1), 1e-6);
        assertEquals(1000 + 250, last.yMm(1), 1e-6);
        assertEquals(90, last.headingDeg(1), 1e-9);
        assertEquals(List.of("done forward 500", "done left 90", "done forward 250"), replies);
    }

    private static void drive(Robot robot, List<String> replies) throws InterruptedException {
        for (String c : new String[] {"forward 500", "jump", "forward NaN", "left 90", "forward 250"}) {
            robot.send("rc", c);
        }
        while (true) {
            Message m = robot.waitForMessage(10_000);
            if (m != null) {
                synchronized (replies) {
                    replies.add(m.text());
                }
            }
        }
    }
}
