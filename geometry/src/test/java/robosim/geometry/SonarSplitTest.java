package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.ObstacleShape;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;

/**
 * The sonar pass split over two cores gives the answer of the pass on one, bit for bit: 300 robots of 16
 * sonars in a cluttered arena driven at random for 30 steps, some not asking for sonar, one engine always
 * splitting and one never; every move, contact and range equal at every step.
 */
class SonarSplitTest {
    @Test
    void theSplitPassGivesTheSerialPassesAnswerBitForBit() {
        int n = 300;
        List<SonarSpec> ring = new ArrayList<>();
        for (int s = 0; s < 16; s++) {
            ring.add(new SonarSpec(250 * Math.cos(Math.toRadians(s * 22.5)), 250 * Math.sin(Math.toRadians(s * 22.5)),
                    s * 22.5, 15, 5000));
        }
        List<RobotProperties> props = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            props.add(new RobotProperties("Test", 250, 1000, 300, ring));
        }
        Arena arena = new Arena(0, 0, 50_000, 50_000);
        List<ObstacleShape> obstacles = new ArrayList<>();
        Random random = new Random(7);
        for (int o = 0; o < 40; o++) {
            obstacles.add(ObstacleShape.rectangle("o" + o, 2000 + random.nextDouble() * 44_000,
                    2000 + random.nextDouble() * 44_000, 300 + random.nextDouble() * 2000, 300 + random.nextDouble() * 2000));
        }
        GeometryEngine split = new GeometryEngine(new StaticWorld(arena, obstacles), props, 1);
        GeometryEngine serial = new GeometryEngine(new StaticWorld(arena, obstacles), props, 0);
        double[][] poses = new double[n][];
        for (int i = 0; i < n; i++) {
            poses[i] = new double[] {1000 + (i % 24) * 2000, 1000 + (i / 24) * 1900, random.nextDouble() * 360};
        }
        int ranges = 0;
        for (int k = 0; k < 30; k++) {
            GeometryStepRequest q = new GeometryStepRequest(n);
            for (int i = 0; i < n; i++) {
                q.set(i, poses[i][0], poses[i][1], poses[i][2], random.nextDouble() * 60 - 30,
                        random.nextDouble() * 700 - 100, random.nextInt(5) != 0);
            }
            GeometryStepResponse a = split.newResponse();
            GeometryStepResponse b = serial.newResponse();
            split.step(q, a);
            serial.step(q, b);
            assertEquals(b.rangeCount(), a.rangeCount(), "ranges at step " + k);
            for (int r = 0; r < b.rangeCount(); r++) {
                assertEquals(Double.doubleToRawLongBits(b.rangeMm(r)), Double.doubleToRawLongBits(a.rangeMm(r)),
                        "range " + r + " at step " + k);
            }
            ranges += b.rangeCount();
            for (int i = 0; i < n; i++) {
                assertEquals(b.movedMm(i), a.movedMm(i), "robot " + i + " at step " + k);
                assertEquals(b.contactKind(i), a.contactKind(i));
                assertEquals(b.contactIndex(i), a.contactIndex(i));
                double h = Kinematics.turn(poses[i][2], b.turnedDeg(i));
                poses[i] = new double[] {poses[i][0] + Kinematics.dx(h, b.movedMm(i)),
                    poses[i][1] + Kinematics.dy(h, b.movedMm(i)), h};
            }
        }
        assertTrue(ranges > 30 * n * 16 / 2, "most robots read their sonars: " + ranges);
    }
}
