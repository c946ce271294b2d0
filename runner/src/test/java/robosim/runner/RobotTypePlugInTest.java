package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import robosim.api.Robot;
import robosim.api.RobotControl;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Settings;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.protocol.ProtocolException;

/** A new robot type is one class on the Hardware Simulator's side; the Environment learns it from the handshake. */
class RobotTypePlugInTest {
    /** Drives 3 m ahead: the arena edge stops it; records its sonar count. */
    static final class Drive implements RobotControl {
        int sonars;
        double moved;

        @Override
        public void run(Robot robot) throws InterruptedException {
            moved = robot.move(3000);
            sonars = robot.sonarRanges().length;
        }
    }

    @Test
    void aHexapodRunsWithItsOwnShapeAndSonars() throws Exception {
        assertEquals(Hexapod.class, robosim.devices.RobotTypes.byName(Hexapod.class.getName()).getClass());
        Drive[] drive = new Drive[1];
        InJvmSimulation sim = new InJvmSimulation(Path.of("src/test/resources/hexapod.xml"))
                .run(20, false, () -> drive[0] = new Drive());
        assertEquals(6, drive[0].sonars, "the Environment used the sonar layout from the handshake");
        // from x = 1 m with radius 0.3 m, the arena edge at 6 m stops it after 4.7 m - but it asked for 3 m
        assertEquals(3000, drive[0].moved, 1e-9);
        assertEquals(4000, sim.updates.get(sim.updates.size() - 1).xMm(0), 1e-9);
    }

    @Test
    void aRobotWhoseRadiusContradictsTheFileIsRefusedSayingWhich() throws Exception {
        var spec = new EnvironmentLoader().load(Path.of("src/test/resources/hexapod.xml"));
        try (ClientWorkerCoordinator env = new ClientWorkerCoordinator(spec, Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true).maxSteps(5)
                .resetEvery(64).handshakeTimeoutMs(10_000).build())) {
            env.start();
            HardwareSimulator fat = new HardwareSimulator("h1", new Hexapod(350));
            ProtocolException e = assertThrows(ProtocolException.class,
                    () -> fat.connect(new Socket(InetAddress.getLoopbackAddress(), env.ports()[0]), 64));
            assertEquals("the Environment refused robot h1: robot h1 has radius 0.3 m in src/test/resources/hexapod.xml,"
                    + " but says 0.35 m", e.getMessage());
        }
    }
}
