package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.io.WKTReader;
import robosim.protocol.Arena;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.ObstacleShape;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;

/** Collision and sonar cases with numbers worked out by hand; JTS checks the no-overlap property. */
class GeometryEngineTest {
    private static final Arena BIG = new Arena(-100_000, -100_000, 100_000, 100_000);
    private static final double GAP = GeometryEngine.CONTACT_GAP_MM;

    /** A round robot of radius 250 with one forward sonar on its rim (15 degree cone, 5 m). */
    private static RobotProperties robot(SonarSpec... sonars) {
        return new RobotProperties("Test", 250, 1000, 300, List.of(sonars));
    }

    private static final SonarSpec FRONT = new SonarSpec(250, 0, 0, 15, 5000);

    private static GeometryStepResponse step(GeometryEngine engine, double[][] poses, double[] turns,
            double[] moves, boolean sonar) {
        GeometryStepRequest q = new GeometryStepRequest(poses.length);
        for (int i = 0; i < poses.length; i++) {
            q.set(i, poses[i][0], poses[i][1], poses[i][2], turns[i], moves[i], sonar);
        }
        GeometryStepResponse r = engine.newResponse();
        engine.step(q, r);
        return r;
    }

    private static GeometryEngine engine(List<ObstacleShape> obstacles, int robots, SonarSpec... sonars) {
        List<RobotProperties> props = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            props.add(robot(sonars));
        }
        return new GeometryEngine(new StaticWorld(BIG, obstacles), props);
    }

    private static final ObstacleShape WALL = ObstacleShape.rectangle("wall", 5000, -2000, 100, 4000);

    @Test
    void sonarTwoMetresFromAWallReads2000() {
        // robot centre 2750, its sonar on the rim at x = 3000, the wall's face at x = 5000
        GeometryEngine e = engine(List.of(WALL), 1, FRONT);
        GeometryStepResponse r = step(e, new double[][] {{2750, 0, 0}}, new double[] {0}, new double[] {0}, true);
        assertEquals(1, r.rangeCount());
        assertEquals(2000, r.rangeMm(0), 1.0);
        assertEquals(2000, r.rangeMm(0), 1e-9);
    }

    @Test
    void sonarReadsMaxRangeWhenNothingIsInTheCone() {
        GeometryEngine e = engine(List.of(WALL), 1, FRONT);
        // facing away from the wall, towards an arena edge 100 m off
        GeometryStepResponse r = step(e, new double[][] {{2750, 0, 180}}, new double[] {0}, new double[] {0}, true);
        assertEquals(5000, r.rangeMm(0));
    }

    @Test
    void sonarSeesOnlyThePartOfAWallInsideItsCone() {
        // sonar at the origin facing +x, half-angle 7.5 degrees; a wall at x = 2000 spanning y 200..1000.
        // tan(7.5) * 2000 = 263.3 > 200, so the wall enters the cone; its nearest point inside is (2000, 200).
        ObstacleShape sliver = ObstacleShape.rectangle("sliver", 2000, 200, 10, 800);
        GeometryEngine e = engine(List.of(sliver), 1, new SonarSpec(0, 0, 0, 15, 5000));
        GeometryStepResponse r = step(e, new double[][] {{0, 0, 0}}, new double[] {0}, new double[] {0}, true);
        assertEquals(Math.hypot(2000, 200), r.rangeMm(0), 1e-9);
        // at y 300..1000 it is outside the cone (tan(7.5) * 2010 = 264.6 < 300): max range
        ObstacleShape outside = ObstacleShape.rectangle("outside", 2000, 300, 10, 700);
        GeometryEngine e2 = engine(List.of(outside), 1, new SonarSpec(0, 0, 0, 15, 5000));
        assertEquals(5000, step(e2, new double[][] {{0, 0, 0}}, new double[] {0}, new double[] {0}, true).rangeMm(0));
    }

    @Test
    void sonarSeesAnotherRobot() {
        // sonar origin at x = 250 (rim of robot 0 at the origin); robot 1's centre at 3250, radius 250: 2750
        GeometryEngine e = engine(List.of(), 2, FRONT);
        GeometryStepResponse r = step(e, new double[][] {{0, 0, 0}, {3250, 0, 0}}, new double[] {0, 0},
                new double[] {0, 0}, true);
        assertEquals(2750, r.rangeMm(0), 1e-9);
        // robot 1's sonar faces +x too, away from robot 0: max range
        assertEquals(5000, r.rangeMm(1));
    }

    @Test
    void sonarSeesARobotAtTheEdgeOfTheCone() {
        // robot 1 at (3000, 600): its centre is at 11.3 degrees, outside the 7.5 degree half-cone, but its
        // disc (r = 250) reaches into it; the nearest point inside lies on the upper boundary ray.
        GeometryEngine e = engine(List.of(), 2, new SonarSpec(0, 0, 0, 15, 5000));
        GeometryStepResponse r = step(e, new double[][] {{0, 0, 0}, {3000, 600, 0}}, new double[] {0, 0},
                new double[] {0, 0}, true);
        double a = Math.toRadians(7.5);
        double ux = Math.cos(a);
        double uy = Math.sin(a);
        double b = -(3000 * ux + 600 * uy);
        double c = 3000 * 3000 + 600 * 600 - 250 * 250;
        double expected = -b - Math.sqrt(b * b - c);
        assertEquals(expected, r.rangeMm(0), 1e-9);
    }

    @Test
    void aRobotDrivenIntoAWallEndsTouchingItNotInsideIt() throws Exception {
        GeometryEngine e = engine(List.of(WALL), 1);
        GeometryStepResponse r = step(e, new double[][] {{4000, 0, 0}}, new double[] {0}, new double[] {1000}, false);
        assertEquals(750 - GAP, r.movedMm(0), 1e-9);
        assertEquals(GeometryStepResponse.CONTACT_OBSTACLE, r.contactKind(0));
        assertEquals(0, r.contactIndex(0));
        Geometry wall = new WKTReader().read("POLYGON ((5000 -2000, 5100 -2000, 5100 2000, 5000 2000, 5000 -2000))");
        double clearance = wall.distance(new GeometryFactory().createPoint(new Coordinate(4000 + r.movedMm(0), 0)));
        assertTrue(clearance >= 250, "not inside: clearance " + clearance);
        assertEquals(250, clearance, 1e-3, "touching");
    }

    @Test
    void aRobotThatIsTouchingMayBackAwayButNotGoFurtherIn() {
        GeometryEngine e = engine(List.of(WALL), 1);
        double touching = 4750 - GAP;
        assertEquals(0, step(e, new double[][] {{touching, 0, 0}}, new double[] {0}, new double[] {100}, false)
                .movedMm(0), 1e-9);
        assertEquals(-100, step(e, new double[][] {{touching, 0, 0}}, new double[] {0}, new double[] {-100}, false)
                .movedMm(0), 1e-12);
        // sliding along the wall face (heading 90) is free
        assertEquals(300, step(e, new double[][] {{touching, 0, 90}}, new double[] {0}, new double[] {300}, false)
                .movedMm(0), 1e-12);
    }

    @Test
    void aRobotGrazingACornerStopsWhereItsRimMeetsTheVertex() {
        // box corner at (5000, 5000); a robot at y = 4800 driving +x meets the vertex when
        // (x - 5000)^2 + 200^2 = 250^2, at x = 4850: it moves 1850 from x = 3000
        ObstacleShape box = ObstacleShape.rectangle("box", 5000, 5000, 1000, 1000);
        GeometryEngine e = engine(List.of(box), 1);
        GeometryStepResponse r = step(e, new double[][] {{3000, 4800, 0}}, new double[] {0}, new double[] {5000},
                false);
        assertEquals(1850 - GAP, r.movedMm(0), 1e-9);
    }

    @Test
    void aRobotThatHasLeftNeitherBlocksNorEchoesNorMoves() {
        GeometryEngine e = engine(List.of(), 2, FRONT);
        GeometryStepRequest q = new GeometryStepRequest(2);
        q.set(0, 1000, 0, 0, 0, 1000, true);
        q.set(1, 2000, 0, 0, 90, 300, true);
        q.setAbsent(1);
        GeometryStepResponse r = e.newResponse();
        e.step(q, r);
        assertEquals(1000, r.movedMm(0), 1e-9, "drives through where robot 1 stood");
        assertEquals(GeometryStepResponse.CONTACT_NONE, r.contactKind(0));
        assertEquals(0, r.movedMm(1));
        assertEquals(0, r.turnedDeg(1));
        assertEquals(1, r.rangeCount(), "ranges for robot 0 only");
        assertEquals(5000, r.rangeMm(0), "robot 1 gives no echo");
    }

    @Test
    void aRobotDrivenIntoAnotherRobotStopsAtContact() {
        GeometryEngine e = engine(List.of(), 2);
        GeometryStepResponse r = step(e, new double[][] {{1000, 0, 0}, {2000, 0, 0}}, new double[] {0, 0},
                new double[] {1000, 0}, false);
        assertEquals(500 - GAP, r.movedMm(0), 1e-9);
        assertEquals(GeometryStepResponse.CONTACT_ROBOT, r.contactKind(0));
        assertEquals(1, r.contactIndex(0));
        assertEquals(GeometryStepResponse.CONTACT_NONE, r.contactKind(1));
    }

    @Test
    void robotsAreResolvedInWorldOrderAgainstWhereOthersAreSoFar() {
        // robot 0 moves away first, so robot 1 may follow into the freed space
        GeometryEngine e = engine(List.of(), 2);
        GeometryStepResponse r = step(e, new double[][] {{1000, 0, 0}, {500, 0, 0}}, new double[] {0, 0},
                new double[] {300, 250}, false);
        assertEquals(300, r.movedMm(0));
        assertEquals(250, r.movedMm(1));
        assertEquals(GeometryStepResponse.CONTACT_NONE, r.contactKind(1));
    }

    @Test
    void theArenaEdgeStopsARobot() {
        Arena small = new Arena(0, 0, 10_000, 10_000);
        GeometryEngine e = new GeometryEngine(new StaticWorld(small, List.of()), List.of(robot()));
        GeometryStepResponse r = step(e, new double[][] {{9000, 5000, 0}}, new double[] {0}, new double[] {2000},
                false);
        assertEquals(750 - GAP, r.movedMm(0), 1e-9);
        assertEquals(GeometryStepResponse.CONTACT_ARENA, r.contactKind(0));
    }

    @Test
    void turnsComeBeforeTheMoveAndNeverCollide() {
        GeometryEngine e = engine(List.of(WALL), 1);
        // touching the wall facing it, turn 180 then move 100 away: allowed in full
        GeometryStepResponse r = step(e, new double[][] {{4750 - GAP, 0, 0}}, new double[] {180},
                new double[] {100}, false);
        assertEquals(180, r.turnedDeg(0));
        assertEquals(100, r.movedMm(0));
    }

    @Test
    void randomDrivingInAClutteredArenaNeverOverlapsAnything() {
        Random random = new Random(42);
        Arena arena = new Arena(0, 0, 8000, 8000);
        List<ObstacleShape> obstacles = List.of(ObstacleShape.rectangle("a", 2000, 2000, 1000, 300),
                new ObstacleShape("tri", new double[] {5000, 5000, 6500, 5200, 5600, 6400}),
                ObstacleShape.rectangle("b", 1000, 5500, 300, 1500));
        int n = 12;
        List<RobotProperties> props = new ArrayList<>();
        double[][] poses = new double[n][];
        for (int i = 0; i < n; i++) {
            props.add(robot(FRONT));
            poses[i] = new double[] {700 + (i % 4) * 2000, 700 + (i / 4) * 2500 + (i % 2) * 300, 0};
        }
        GeometryEngine e = new GeometryEngine(new StaticWorld(arena, obstacles), props);
        GeometryFactory gf = new GeometryFactory();
        List<Geometry> walls = new ArrayList<>();
        for (ObstacleShape o : obstacles) {
            Coordinate[] ring = new Coordinate[o.vertexCount() + 1];
            for (int v = 0; v < o.vertexCount(); v++) {
                ring[v] = new Coordinate(o.x(v), o.y(v));
            }
            ring[o.vertexCount()] = ring[0];
            walls.add(gf.createPolygon(ring));
        }
        int contacts = 0;
        for (int k = 0; k < 2000; k++) {
            double[] turns = new double[n];
            double[] moves = new double[n];
            for (int i = 0; i < n; i++) {
                turns[i] = random.nextInt(4) == 0 ? random.nextDouble() * 90 - 45 : 0;
                moves[i] = random.nextDouble() * 600 - 100;
            }
            GeometryStepResponse r = step(e, poses, turns, moves, true);
            for (int i = 0; i < n; i++) {
                double h = Kinematics.turn(poses[i][2], r.turnedDeg(i));
                poses[i] = new double[] {poses[i][0] + Kinematics.dx(h, r.movedMm(i)),
                    poses[i][1] + Kinematics.dy(h, r.movedMm(i)), h};
                if (r.contactKind(i) != GeometryStepResponse.CONTACT_NONE) {
                    contacts++;
                }
            }
            for (int i = 0; i < n; i++) {
                double x = poses[i][0];
                double y = poses[i][1];
                assertTrue(x >= 250 - 1e-9 && x <= 7750 + 1e-9 && y >= 250 - 1e-9 && y <= 7750 + 1e-9,
                        "robot " + i + " inside the arena at step " + k);
                for (Geometry w : walls) {
                    double d = w.distance(gf.createPoint(new Coordinate(x, y)));
                    assertTrue(d >= 250 - 1e-9, "robot " + i + " overlaps a wall by " + (250 - d) + " at step " + k);
                }
                for (int j = i + 1; j < n; j++) {
                    double d = Math.hypot(x - poses[j][0], y - poses[j][1]);
                    assertTrue(d >= 500 - 1e-9, "robots " + i + " and " + j + " overlap at step " + k);
                }
            }
        }
        assertTrue(contacts > 100, "the run actually pushed robots into things: " + contacts + " contacts");
    }

    @Test
    void kinematicsNormalisesHeadings() {
        assertEquals(180, Kinematics.turn(0, 45 + 45 + 45 + 45));
        assertEquals(270, Kinematics.turn(0, -90));
        assertEquals(10, Kinematics.turn(350, 20), 1e-12);
        assertEquals(-250, Kinematics.dx(180, 250));
    }

    /**
     * A robot that slides ({@link GeometryStepRequest#SLIDE}, a wheeled swarm robot) driven at 45 degrees into a wall
     * stops where it touches, then slides along the wall with what is left of its move times cos 45; one that does not
     * slide only stops; one driven head on does not slide.
     */
    @Test
    void aSlidingRobotGoesOnAlongTheWallWithTheTangentialPartOfItsMove() {
        GeometryEngine e = engine(List.of(WALL), 1);
        // centre (4650, 0), heading 45: it touches the wall's face x = 5000 when x = 4750, after 100 sqrt(2) mm
        for (boolean slides : new boolean[] {true, false}) {
            GeometryStepRequest q = new GeometryStepRequest(1);
            q.set(0, 4650, 0, 45, 0, 400, slides ? GeometryStepRequest.SLIDE : 0);
            GeometryStepResponse r = e.newResponse();
            e.step(q, r);
            double touched = 100 * Math.sqrt(2) - GAP * Math.sqrt(2);
            assertEquals(touched, r.movedMm(0), 1e-6);
            assertEquals(GeometryStepResponse.CONTACT_OBSTACLE, r.contactKind(0));
            if (slides) {
                assertEquals(1, r.slideCount());
                assertEquals(0, r.slideXMm(0), 1e-9, "along the wall's face");
                assertEquals((400 - touched) * Math.cos(Math.toRadians(45)), r.slideYMm(0), 1e-6);
            } else {
                assertEquals(0, r.slideCount());
            }
        }
        GeometryStepRequest q = new GeometryStepRequest(1);
        q.set(0, 4650, 0, 0, 0, 400, GeometryStepRequest.SLIDE);
        GeometryStepResponse r = e.newResponse();
        e.step(q, r);
        assertEquals(100 - GAP, r.movedMm(0), 1e-6);
        assertEquals(0, r.slideCount(), "head on: nothing to slide along");
    }
}
