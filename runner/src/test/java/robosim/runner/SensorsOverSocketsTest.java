package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.api.Robot;
import robosim.api.RobotControl;

/** Control code reads the Environment's sensors through the robot API, over real sockets. */
class SensorsOverSocketsTest {
    /** Reads laser and heat, tags the flag, drives into the wall, reads bump. */
    static final class Probe implements RobotControl {
        final CountDownLatch done = new CountDownLatch(1);
        List<String> names;
        double laserAhead;
        double heat;
        double moved;
        double[] bump;
        String tagged;

        @Override
        public void run(Robot robot) throws InterruptedException {
            names = robot.sensorNames();
            robot.sleep(500);
            laserAhead = robot.sensor("laser")[90];
            heat = robot.sensor("heat")[0];
            tagged = robot.tag();
            moved = robot.move(5000);
            robot.sleep(500);
            bump = robot.sensor("bump");
            done.countDown();
        }
    }

    @Test
    void laserHeatAndBumpReachTheControlCode() throws Exception {
        InJvmSimulation sim = new InJvmSimulation(Path.of("src/test/resources/sensors.xml"));
        Probe[] probe = new Probe[1];
        sim.run(40, false, () -> probe[0] = new Probe());
        assertTrue(probe[0].done.await(10, TimeUnit.SECONDS));
        assertEquals(List.of("laser", "bump", "heat"), probe[0].names);
        assertEquals(3000, probe[0].laserAhead, 1e-9, "the wall's face is 3 m ahead");
        assertEquals(8 / (1 + 0.5 * 0.5), probe[0].heat, 1e-12, "the stove is 0.5 m away, in sight");
        assertEquals(3000 - 250 - robosim.geometry.GeometryEngine.CONTACT_GAP_MM, probe[0].moved, 1e-9);
        assertArrayEquals(new double[] {1, 0, 0, 0}, probe[0].bump, "touching the wall in front");
        assertEquals("flag", probe[0].tagged);
        assertEquals(List.of("s1>flag"), sim.updates.get(sim.updates.size() - 1).tags(), "viewers were told");
    }
}
