package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.runner.InJvmCommand.run;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.geometry.GeometryMain;
import robosim.hardware.MultiRobotMain;
import robosim.hardware.RobotMain;

/**
 * A process that cannot reach the Environment says so in one line naming the host and port (exit 2
 * for a host that does not exist, 1 when nothing answers in time), and says "connecting to HOST:PORT"
 * once while it waits.
 */
class ConnectionErrorsTest {

    @Test
    void aRobotGivenAHostThatDoesNotExistSaysSoInOneLine() {
        var r = run(new RobotMain(), "robosim.examples.BackAndForth", "r1", "nosuchhost.invalid", "8000");
        assertEquals(2, r.code(), r.err().toString());
        assertEquals(List.of("robot r1: cannot connect to the Environment at nosuchhost.invalid:8000: unknown host "
                + "nosuchhost.invalid"), r.err());
    }

    @Test
    void geometryGivenAHostThatDoesNotExistSaysSoInOneLine() {
        var r = run(new GeometryMain(), "nosuchhost.invalid", "10000");
        assertEquals(2, r.code(), r.err().toString());
        assertEquals(List.of("geometry: cannot connect to nosuchhost.invalid:10000: unknown host nosuchhost.invalid"),
                r.err());
    }

    @Test
    void aPortOutOfRangeIsOneLineAndExit2ForRobotsAndGeometry() {
        var robot = run(new RobotMain(), "robosim.examples.BackAndForth", "r1", "localhost", "99999");
        assertEquals(2, robot.code(), robot.err().toString());
        assertEquals(List.of("robot r1: localhost:99999: port 99999 is not a TCP port (1..65535)"), robot.err());
        var robots = run(new robosim.hardware.MultiRobotMain(), "--robot", "r1:ArRobot:robosim.examples.BackAndForth",
                "localhost", "70000");
        assertEquals(2, robots.code(), robots.err().toString());
        assertEquals(List.of("robots: localhost:70000: port 70000 is not a TCP port (1..65535)"), robots.err());
        var geometry = run(new GeometryMain(), "localhost", "-1");
        assertEquals(2, geometry.code(), geometry.err().toString());
        assertEquals(List.of("geometry: localhost:-1: port -1 is not a TCP port (1..65535)"), geometry.err());
    }

    @Test
    void aRobotWaitingForAnEnvironmentThatNeverComesSaysWhatItWaitsForThenGivesUpInOneLine() throws Exception {
        try (Socket reserved = new Socket()) {
            reserved.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0)); // bound, never listening
            String port = Integer.toString(reserved.getLocalPort());
            var r = run(new RobotMain(), "robosim.examples.BackAndForth", "r1", "127.0.0.1", port,
                    "--connect-timeout-s", "1");
            assertEquals(1, r.code(), r.err().toString());
            assertEquals(List.of(
                    "connecting to 127.0.0.1:" + port + " ... (for up to 1 s; is the Environment running?)",
                    "robot r1: cannot connect to the Environment at 127.0.0.1:" + port + " within 1 s (is it running, "
                            + "on that port?)"), r.err());
        }
    }

    @Test
    void manyRobotsInOneProcessSayConnectingOnce() throws Exception {
        try (Socket reserved = new Socket()) {
            reserved.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            String port = Integer.toString(reserved.getLocalPort());
            var r = run(new MultiRobotMain(), "127.0.0.1", port, "--connect-timeout-s", "1",
                    "--robot", "a:ArRobot:robosim.examples.BackAndForth",
                    "--robot", "b:ArRobot:robosim.examples.BackAndForth");
            assertEquals(1, r.code(), r.err().toString());
            assertEquals(1, r.err().stream().filter(l -> l.startsWith("connecting to 127.0.0.1:" + port)).count(),
                    r.err().toString());
        }
    }
}
