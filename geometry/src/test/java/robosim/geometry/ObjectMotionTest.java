package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.ObstacleShape;
import robosim.protocol.RaySpec;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;
import robosim.protocol.WorldObject;

/**
 * Objects with numbers worked out by hand: a robot stops at a static box and pushes a movable one (slowed by its load,
 * stopped with it at a wall), pushes a row of them, cannot push what another carries; a gripper takes what touches its
 * front, and the robot carries it along and around a corner; sonar and proximity rays see objects.
 */
class ObjectMotionTest {
    private static final double GAP = GeometryEngine.CONTACT_GAP_MM;
    /** A 4 m x 2 m arena: its right edge at x = 4000. */
    private static final Arena ARENA = new Arena(0, 0, 4000, 2000);

    /** A robot of radius 100, 10 kg, a gripper reaching 10 mm within 30 degrees, one ray straight ahead. */
    private static final RobotProperties ROBOT = new RobotProperties("Test", 100, 100, 10, 1000, 300,
            List.of(new SonarSpec(100, 0, 0, 15, 3000)), List.of(RaySpec.onRim(100, 0, 500)), List.of(),
            new RobotProperties.Gripper(10, 30));

    private static WorldObject box(String name, double x, double y, double side, double massKg, boolean movable) {
        return new WorldObject(name, WorldObject.Shape.BOX, side, side, 100, massKg, 0.5, movable, false, 0, x, y, 0);
    }

    private static WorldObject cylinder(String name, double x, double y, double r, boolean gripable) {
        return new WorldObject(name, WorldObject.Shape.CYLINDER, 2 * r, 2 * r, 100, 1, 0.5, true, gripable, 0, x, y, 0);
    }

    /** One world, its objects kept where the last step left them, as the Environment keeps them. */
    private static final class World {
        final GeometryEngine engine;
        final List<WorldObject> objects;
        final double[][] robots;
        final double[][] objectPoses;
        final int[] carrier;
        GeometryStepResponse last;

        World(List<ObstacleShape> obstacles, List<WorldObject> objects, double[]... robotPoses) {
            List<RobotProperties> props = new ArrayList<>();
            for (int i = 0; i < robotPoses.length; i++) {
                props.add(ROBOT);
            }
            this.engine = new GeometryEngine(new StaticWorld(ARENA, obstacles), props, objects, 0);
            this.objects = objects;
            this.robots = robotPoses;
            this.objectPoses = new double[objects.size()][];
            this.carrier = new int[objects.size()];
            for (int o = 0; o < objects.size(); o++) {
                objectPoses[o] = new double[] {objects.get(o).xMm(), objects.get(o).yMm(), objects.get(o).headingDeg()};
                carrier[o] = -1;
            }
        }

        /** One step: robot i turns turns[i], then moves moves[i]; {@code grip}: robot 0 grips after. */
        GeometryStepResponse step(double[] turns, double[] moves, boolean grip) {
            GeometryStepRequest q = new GeometryStepRequest(robots.length, objects.size());
            for (int i = 0; i < robots.length; i++) {
                byte flags = (byte) (GeometryStepRequest.SONAR | GeometryStepRequest.RAYS
                        | (grip && i == 0 ? GeometryStepRequest.GRIP : 0));
                q.set(i, robots[i][0], robots[i][1], robots[i][2], turns[i], moves[i], flags);
            }
            for (int o = 0; o < objects.size(); o++) {
                q.setObject(o, objectPoses[o][0], objectPoses[o][1], objectPoses[o][2], carrier[o]);
            }
            GeometryStepResponse r = engine.newResponse();
            engine.step(q, r);
            for (int i = 0; i < robots.length; i++) { // (as the Environment applies an answer)
                double h = Kinematics.turn(robots[i][2], r.turnedDeg(i));
                robots[i] = new double[] {robots[i][0] + Kinematics.dx(h, r.movedMm(i)),
                    robots[i][1] + Kinematics.dy(h, r.movedMm(i)), h};
            }
            for (int o = 0; o < objects.size(); o++) {
                objectPoses[o] = new double[] {r.objectXMm(o), r.objectYMm(o), r.objectHeadingDeg(o)};
            }
            for (int k = 0; k < r.gripCount(); k++) {
                if (r.gripObject(k) >= 0) {
                    carrier[r.gripObject(k)] = r.gripRobot(k);
                }
            }
            last = r;
            return r;
        }

        GeometryStepResponse move(double mm) {
            double[] moves = new double[robots.length];
            moves[0] = mm;
            return step(new double[robots.length], moves, false);
        }
    }

    @Test
    void anObjectOutOfTheWorldIsNotMetSeenOrGripped() {
        // a can 5 mm from the robot's rim, in its gripper's reach and its ray's
        List<WorldObject> can = List.of(cylinder("can", 655, 1000, 50, true));
        World in = new World(List.of(), can, new double[] {500, 1000, 0});
        GeometryStepResponse seen = in.step(new double[1], new double[1], true);
        assertEquals(5, seen.rayMm(0), 1e-9, "in the world: seen");
        assertEquals(0, seen.gripObject(0), "and gripped");
        World out = new World(List.of(), can, new double[] {500, 1000, 0});
        out.carrier[0] = GeometryStepRequest.GONE; // (the loop functions took it out)
        GeometryStepResponse r = out.step(new double[1], new double[1], true);
        assertEquals(500, r.rayMm(0), 1e-9, "out of the world: nothing seen, the ray's whole range");
        assertEquals(-1, r.gripObject(0), "nothing to grip");
        r = out.move(500);
        assertEquals(500, r.movedMm(0), 1e-9, "through where it is");
        assertEquals(GeometryStepResponse.CONTACT_NONE, r.contactKind(0));
        assertEquals(655, r.objectXMm(0), "it stays where it was");
    }

    @Test
    void aRobotStopsAtABoxThatDoesNotMove() {
        // the robot's rim at x 600, the box's near face at 900: 300 mm to go of the 500 asked
        World w = new World(List.of(), List.of(box("crate", 1000, 1000, 200, 1, false)), new double[] {500, 1000, 0});
        GeometryStepResponse r = w.move(500);
        assertEquals(300 - GAP, r.movedMm(0), 1e-9);
        assertEquals(GeometryStepResponse.CONTACT_OBJECT, r.contactKind(0));
        assertEquals(0, r.contactIndex(0));
        assertEquals(1000, r.objectXMm(0));
    }

    @Test
    void aPushedBoxMovesAtTheRobotsPaceSlowedByItsLoadAndStopsAtTheWall() {
        // rim at 600, box (200 wide, 1 kg... here 10 kg, friction 0.5) near face at 800: 200 mm free, then the box
        World w = new World(List.of(), List.of(box("crate", 900, 1000, 200, 10, true)), new double[] {500, 1000, 0});
        GeometryStepResponse r = w.move(500);
        // 200 free of the 500 (0.4 of the step), the rest (0.6) at 10 / (10 + 0.5 x 10) = 2/3 pace: 200 more
        double free = 200 - GAP;
        double pushed = (1 - free / 500) * 500 * 10 / 15;
        assertEquals(free + pushed, r.movedMm(0), 1e-9);
        assertEquals(900 + pushed, r.objectXMm(0), 1e-9);
        assertEquals(GeometryStepResponse.CONTACT_OBJECT, r.contactKind(0));
        // on until the box's far face meets the arena's edge at 4000: it goes no further, nor does the robot
        for (int k = 0; k < 20; k++) {
            w.move(500);
        }
        assertEquals(4000 - 100 - GAP, w.objectPoses[0][0], 1e-6);
        assertEquals(4000 - 200 - GAP - 100 - GAP, w.robots[0][0], 1e-6);
        assertEquals(GeometryStepResponse.CONTACT_OBJECT, w.last.contactKind(0));
        assertEquals(0, w.last.movedMm(0), 1e-9);
    }

    @Test
    void aHeavierLoadSlowsTheRobotInProportion() {
        // touching the box from the start: the whole step at m / (m + mu M)
        for (double mass : new double[] {1, 10, 100}) {
            World w = new World(List.of(), List.of(box("crate", 700 + GAP, 1000, 200, mass, true)),
                    new double[] {500, 1000, 0});
            GeometryStepResponse r = w.move(300);
            assertEquals(300 * 10 / (10 + 0.5 * mass), r.movedMm(0), 1e-6, mass + " kg");
        }
    }

    @Test
    void aPushedBoxPushesTheNextOneAndTheLoadAddsUp() {
        // box a touching the robot, cylinder b 100 mm beyond it: a alone for 100 mm, then both
        World w = new World(List.of(), List.of(box("a", 700 + GAP, 1000, 200, 2, true),
                cylinder("b", 1000, 1000, 100, false)), new double[] {500, 1000, 0});
        GeometryStepResponse r = w.move(400);
        double alone = 100 - GAP; // (a's far face at 800 + GAP, b's near side at 900)
        double timeLeft = 1 - alone / (400 * 10 / 11.0);
        double both = timeLeft * 400 * 10 / 11.5;
        assertEquals(alone + both, r.movedMm(0), 1e-6);
        assertEquals(700 + GAP + alone + both, r.objectXMm(0), 1e-6);
        assertEquals(1000 + both, r.objectXMm(1), 1e-6);
    }

    @Test
    void noObjectIsPushedIntoAWallOrAnotherRobot() {
        ObstacleShape wall = ObstacleShape.rectangle("wall", 1200, 0, 100, 2000);
        World w = new World(List.of(wall), List.of(box("crate", 900, 1000, 200, 1, true)),
                new double[] {500, 1000, 0}, new double[] {1500, 1000, 180});
        for (int k = 0; k < 5; k++) {
            w.move(300);
        }
        assertEquals(1200 - 100 - GAP, w.objectPoses[0][0], 1e-6, "against the wall's face");
        assertEquals(GeometryStepResponse.CONTACT_OBJECT, w.last.contactKind(0));
    }

    @Test
    void aGripperTakesWhatTouchesItsFrontAndTheRobotCarriesItAroundACorner() {
        // a gripable cylinder (r 50) touching the robot's front; another robot's load is not its to take
        World w = new World(List.of(), List.of(cylinder("can", 650 + GAP, 1000, 50, true)), new double[] {500, 1000, 0});
        GeometryStepResponse r = w.step(new double[] {0}, new double[] {0}, true);
        assertEquals(1, r.gripCount());
        assertEquals(0, r.gripObject(0), "the can");
        // drive 1 m: the can goes with it, the same distance
        w.move(1000);
        assertEquals(1650 + GAP, w.objectPoses[0][0], 1e-6);
        assertEquals(1000, w.objectPoses[0][1], 1e-6);
        // turn left 90 degrees: the can swings round the robot's centre to its new front
        w.step(new double[] {90}, new double[] {0}, false);
        assertEquals(1500, w.objectPoses[0][0], 1e-6);
        assertEquals(1150 + GAP, w.objectPoses[0][1], 1e-6);
        // drive up towards the far edge (y 2000): the can meets it first, and the robot stops with it
        for (int k = 0; k < 4; k++) {
            w.move(500);
        }
        assertEquals(2000 - 50 - GAP, w.objectPoses[0][1], 1e-6);
        assertEquals(2000 - 50 - GAP - 150 - GAP, w.robots[0][1], 1e-6);
    }

    @Test
    void aTurnThatWouldSwingTheLoadIntoAWallStopsWhereItTouches() {
        // carrying a can at its front, facing +x, a wall 20 mm above the robot's front-left
        ObstacleShape wall = ObstacleShape.rectangle("wall", 0, 1120, 4000, 100);
        World w = new World(List.of(wall), List.of(cylinder("can", 650 + GAP, 1000, 50, true)),
                new double[] {500, 1000, 0});
        w.step(new double[] {0}, new double[] {0}, true);
        GeometryStepResponse r = w.step(new double[] {90}, new double[] {0}, false);
        // the can's centre circles at 150 from (500, 1000); it touches the wall when 1000 + 150 sin(a) + 50 = 1120
        double a = Math.toDegrees(Math.asin(70 / (150 + GAP)));
        assertEquals(a, r.turnedDeg(0), 1e-3);
        assertTrue(w.objectPoses[0][1] + 50 <= 1120 + 1e-6);
    }

    @Test
    void nothingInReach() {
        World w = new World(List.of(), List.of(cylinder("can", 800, 1000, 50, true)), new double[] {500, 1000, 0});
        GeometryStepResponse r = w.step(new double[] {0}, new double[] {0}, true);
        assertEquals(-1, r.gripObject(0), "150 mm away: out of reach");
        World beside = new World(List.of(), List.of(cylinder("can", 500, 1150 + GAP, 50, true)),
                new double[] {500, 1000, 0});
        assertEquals(-1, beside.step(new double[] {0}, new double[] {0}, true).gripObject(0), "at its side");
    }

    @Test
    void aLoadCannotBeTakenOrPushedByAnother() {
        World w = new World(List.of(), List.of(cylinder("can", 650 + GAP, 1000, 50, true)),
                new double[] {500, 1000, 0}, new double[] {1000, 1000, 180});
        w.step(new double[] {0, 0}, new double[] {0, 0}, true);
        assertEquals(0, w.carrier[0]);
        GeometryStepResponse r = w.step(new double[] {0, 0}, new double[] {0, 500}, false);
        // robot 1 (rim at 900) runs into the can (its far side at 700 + GAP): it stops, the can stays
        assertEquals(200 - 2 * GAP, r.movedMm(1), 1e-6);
        assertEquals(GeometryStepResponse.CONTACT_OBJECT, r.contactKind(1));
        assertEquals(650 + GAP, w.objectPoses[0][0], 1e-9);
    }

    @Test
    void sonarAndRaysSeeObjects() {
        // a box whose near face is 400 mm from the robot's rim, where both its sonar and its ray start
        World w = new World(List.of(), List.of(box("crate", 1100, 1000, 200, 1, false)), new double[] {500, 1000, 0});
        GeometryStepResponse r = w.move(0);
        assertEquals(400, r.rangeMm(0), 1e-9);
        assertEquals(1, r.rayCount());
        assertEquals(400, r.rayMm(0), 1e-9);
        World none = new World(List.of(), List.of(), new double[] {500, 1000, 0});
        assertEquals(500, none.move(0).rayMm(0), 1e-9, "the ray's range when nothing is in it");
    }
}
