package robosim.testkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.api.Colours;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * A foot-bot's wheels, gripper, LEDs and range-and-bearing device through the robot API, in a whole simulation
 * (test-envs/gripping.xml: the carrier faces a can 5 mm ahead of its rim, the watcher stands 0.5 m to its left):
 * values out of range refused with the value and the code goes on, a grip with nothing in reach answers "", a held
 * can carried, the wheels' distance worked out by hand.
 */
class DevicesTest {
    private static final Path GRIPPING = Path.of("..", "test-envs", "gripping.xml");

    private static String refusal(Runnable call) {
        try {
            call.run();
            return "accepted";
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
    }

    @Test
    void aFootBotDrivesOnItsWheelsGripsCarriesAndLetsGoAndBadValuesAreRefused() throws Exception {
        List<String> carrier = new ArrayList<>();
        List<String> watcher = new ArrayList<>();
        double[] x = new double[3];
        RobotControl carry = robot -> {
            robot.step();
            x[0] = robot.xMm();
            carrier.add(refusal(() -> robot.setWheelSpeeds(400, 0)));
            carrier.add(refusal(() -> robot.setLed(0, 0x1000000)));
            carrier.add(refusal(() -> robot.setRabData(1, 2)));
            robot.setLeds(Colours.RED);
            carrier.add(robot.grip());
            robot.setWheelSpeeds(100, 100); // (10 mm a step of 100 ms, the can ahead of it)
            for (int s = 0; s < 10; s++) {
                robot.step();
            }
            x[1] = robot.xMm();
            carrier.add(robot.gripped());
            robot.setWheelSpeeds(0, 0);
            robot.release();
            carrier.add(robot.gripped());
            robot.setWheelSpeeds(-100, -100);
            for (int s = 0; s < 10; s++) {
                robot.step();
            }
            x[2] = robot.xMm();
            while (true) {
                robot.step();
            }
        };
        RobotControl watch = robot -> {
            watcher.add(robot.grip());
            robot.step();
            double[] blobs = robot.sensor("camera");
            watcher.add(blobs.length > 0 ? Integer.toHexString((int) blobs[0]) : "none");
            while (true) {
                robot.step();
            }
        };
        try (Simulation sim = Simulation.of(GRIPPING).control("carrier", carry).control("watcher", watch).start()) {
            sim.run(40);
        }
        assertTrue(carrier.get(0).contains("400"), "a wheel beyond the top speed: " + carrier.get(0));
        assertTrue(carrier.get(1).contains("16777216"), "not a colour: " + carrier.get(1));
        assertEquals("rab takes 10 values, got 2", carrier.get(2));
        assertEquals(List.of("can", "can", ""), carrier.subList(3, 6), "gripped, held, let go");
        assertEquals(100, x[1] - x[0], 1e-6, "10 steps at 100 mm/s of 100 ms, the can carried ahead");
        assertEquals(-100, x[2] - x[1], 1e-6, "and back, the can left where it was let go");
        assertEquals("", watcher.get(0), "a grip with nothing in reach takes nothing, and the code goes on");
        assertEquals("ff0000", watcher.get(1), "the carrier's red LEDs in the watcher's camera");
    }
}
