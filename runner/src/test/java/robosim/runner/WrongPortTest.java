package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static robosim.runner.InJvmCommand.run;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.control.ControlClient;
import robosim.control.ControlPanelMain;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.control.ControlServer;
import robosim.environment.control.EnvironmentCommands;
import robosim.environment.control.EnvironmentDirectories;
import robosim.environment.control.EnvironmentHost;
import robosim.environment.run.Settings;
import robosim.geometry.GeometryMain;
import robosim.hardware.MultiRobotMain;
import robosim.hardware.RobotMain;
import robosim.protocol.SimulationKeys;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;

/**
 * A client at a port of another kind (robot.sh, robots.sh, viewer2d, geometry.sh, control-panel.sh) ends at once with one line naming the host:port and what answered there,
 * and a non-zero exit (issue 31, item 1); a client without keys at an Environment that speaks TLS is told to
 * set ROBOSIM_KEYS at once (item 7). The Environment goes on serving its own clients.
 */
class WrongPortTest {
    private static EnvironmentHost host;
    private static ControlServer control;
    private static int robots;
    private static int viewers;
    private static int geometry;
    private static int controlPort;
    private static robosim.web.WebViewerServer web;



    /** What the control port tells a client of the object protocol. */
    private static String robosimControlRefusal() {
        return "that is the Environment's control port (the Control Panel's); robots, viewers and Geometry use the "
                + "Environment's own ports (8000, 3000 and 10000 by default)";
    }

    @BeforeAll
    static void environment() throws Exception {
        Path file = InJvmSimulation.env("test.xml");
        Settings s = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(false)
                .build();
        host = new EnvironmentHost(file, new EnvironmentLoader().load(file), s, true, true);
        host.open();
        control = new ControlServer(new EnvironmentCommands(host, new EnvironmentDirectories(List.of(
                file.toAbsolutePath().getParent()))), null, 0);
        control.start(InetAddress.getLoopbackAddress(), 0);
        CompletableFuture.runAsync(() -> {
            try {
                host.run(summary -> { });
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, TestThreads.ROBOTS);
        int[] ports = host.ports();
        robots = ports[0];
        viewers = ports[1];
        geometry = ports[2];
        controlPort = control.port();
        web = new robosim.web.WebViewerServer("127.0.0.1", viewers, null, (verb, arg) -> "{\"ok\":true}");
        web.start(InetAddress.getLoopbackAddress(), 0);
    }

    @AfterAll
    static void close() throws Exception {
        web.close();
        control.close();
        host.shutdown();
    }

    @Test
    void aRobotAtAnotherPortIsToldWhichPortItWants() {
        var atViewers = run(new RobotMain(), "robosim.examples.BackAndForth", "rc1", "127.0.0.1", "" + viewers);
        assertEquals(1, atViewers.code(), atViewers.err().toString());
        assertEquals(List.of("robot rc1: 127.0.0.1:" + viewers + ": that is the Environment's viewer port; robots use "
                + robots), atViewers.err());
        var atGeometry = run(new RobotMain(), "robosim.examples.BackAndForth", "rc1", "127.0.0.1", "" + geometry);
        assertEquals(List.of("robot rc1: 127.0.0.1:" + geometry + ": that is the Environment's Geometry port; robots use "
                + robots), atGeometry.err());
        var atControl = run(new RobotMain(), "robosim.examples.BackAndForth", "rc1", "127.0.0.1", "" + controlPort);
        assertEquals(1, atControl.code(), atControl.err().toString());
        assertEquals(List.of("robot rc1: 127.0.0.1:" + controlPort + ": " + robosimControlRefusal()), atControl.err());
    }

    @Test
    void aRobotAtTheWebPortIsToldAndTheControlPanelToo() {
        var robot = run(new RobotMain(), "robosim.examples.BackAndForth", "rc1", "127.0.0.1", "" + web.port());
        assertEquals(1, robot.code(), robot.err().toString());
        assertEquals(List.of("robot rc1: 127.0.0.1:" + web.port() + ": that is the Environment's web port (a browser's); "
                + "robots, viewers and Geometry use the Environment's own ports (8000, 3000 and 10000 by default)"),
                robot.err());
        var panel = run(new ControlPanelMain(), "127.0.0.1", "" + web.port(), "status");
        assertEquals(1, panel.code(), panel.out() + panel.err());
        assertTrue(panel.out().contains("error=that is the Environment's web port (a browser's); the Control Panel uses "
                + "the control port (8100 by default)"), panel.out());
    }

    @Test
    void aBrowserAtTheRobotPortGetsA400SayingWhatThePortIs() throws Exception {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), robots)) {
            s.getOutputStream().write("GET / HTTP/1.1\r\nHost: localhost\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
            String answer = new String(s.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(answer.startsWith("HTTP/1.1 400 Bad Request\r\n"), answer);
            assertTrue(answer.endsWith("\r\n\r\nthis is the Environment's robot port, which speaks RoboSim's object "
                    + "protocol (robots, viewers, Geometry); the Control Panel uses the control port (8100 by default), a "
                    + "browser the web port (--web-port)\n"), answer);
        }
    }

    @Test
    void severalRobotsOverOneConnectionAtTheViewerPortAreToldToo() {
        var r = run(new MultiRobotMain(), "127.0.0.1", "" + viewers, "--robot", "a:ArRobot:robosim.examples.BackAndForth");
        assertEquals(1, r.code(), r.err().toString());
        assertEquals(List.of("robots: 127.0.0.1:" + viewers + ": that is the Environment's viewer port; robots use "
                + robots), r.err());
    }

    /** (What viewer2d and a robot window print and exit 1 on, before any window: CI has no display to run them.) */
    @Test
    void aViewerAtTheRobotPortIsToldWhichPortItWants() throws Exception {
        ViewerClient v = ViewerClient.connect("127.0.0.1", robots, new ViewerHello(false, 30), 5_000, null);
        v.close();
        assertEquals("that is the Environment's robot port; viewers use " + viewers, v.refusal().reason());
        ViewerClient atControl = ViewerClient.connect("127.0.0.1", controlPort, new ViewerHello(false, 30), 5_000, null);
        atControl.close();
        assertEquals(robosimControlRefusal(), atControl.refusal().reason());
    }

    @Test
    void geometryAtTheViewerPortIsToldAndExitsNonZero() {
        var r = run(new GeometryMain(), "127.0.0.1", "" + viewers);
        assertEquals(1, r.code(), r.err().toString());
        assertEquals(List.of("geometry: 127.0.0.1:" + viewers + ": that is the Environment's viewer port; Geometry uses "
                + geometry), r.err());
    }

    @Test
    void theControlPanelAtTheRobotPortIsToldWhereTheControlPortIs() {
        var r = run(new ControlPanelMain(), "127.0.0.1", "" + robots, "status");
        assertEquals(1, r.code(), r.out() + r.err());
        assertTrue(r.out().contains("ok=false"), r.out());
        assertTrue(r.out().contains("error=this is the Environment's robot port, which speaks RoboSim's object protocol "
                + "(robots, viewers, Geometry); the Control Panel uses the control port (8100 by default)"), r.out());
    }

    @Test
    void aRobotAtAPortThatNeverAnswersEndsWithinItsTimeoutSayingSo() throws Exception {
        try (ServerSocket silent = new ServerSocket(0, 4, InetAddress.getLoopbackAddress())) {
            var r = run(new RobotMain(), "robosim.examples.BackAndForth", "rc1", "127.0.0.1", "" + silent.getLocalPort(),
                    "--connect-timeout-s", "1");
            assertEquals(1, r.code(), r.err().toString());
            assertEquals(List.of("robot rc1: 127.0.0.1:" + silent.getLocalPort() + ": no answer within 5 s: nothing "
                    + "there speaks RoboSim's object protocol"), r.err());
        }
    }

    @Test
    void theEnvironmentStillServesItsOwnClientsAfterTheStrangers() throws Exception {
        aRobotAtAnotherPortIsToldWhichPortItWants();
        try (ControlClient c = new ControlClient("127.0.0.1", controlPort, null, ControlFixture.TIMEOUT_MS)) {
            assertTrue(c.request("status").path("ok").asBoolean());
        }
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), robots)) {
            new robosim.hardware.HardwareSimulator("robot1", new robosim.devices.ArRobot()).connect(s, 64, null);
        }
    }

    @Test
    void clientsWithoutKeysAtAnEnvironmentThatSpeaksTlsAreToldToSetThem(@TempDir Path dir) throws Exception {
        SimulationKeys keys = TestKeys.keys(dir, "keys");
        Path file = InJvmSimulation.env("test.xml");
        Settings s = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true)
                .keys(keys).build();
        EnvironmentHost tls = new EnvironmentHost(file, new EnvironmentLoader().load(file), s, true, true);
        tls.open();
        ControlServer tlsControl = new ControlServer(new EnvironmentCommands(tls, new EnvironmentDirectories(List.of(
                file.toAbsolutePath().getParent()))), keys, 0);
        tlsControl.start(InetAddress.getLoopbackAddress(), 0);
        try {
            int port = tls.ports()[0];
            var robot = run(new RobotMain(), "robosim.examples.BackAndForth", "r1", "127.0.0.1", "" + port);
            assertEquals(1, robot.code(), robot.err().toString());
            assertEquals(List.of("robot r1: 127.0.0.1:" + port + ": the Environment speaks TLS (tls=on): set "
                    + "ROBOSIM_KEYS to the simulation's keys"), robot.err());
            var panel = run(new ControlPanelMain(), "127.0.0.1", "" + tlsControl.port(), "status");
            assertEquals(1, panel.code(), panel.out() + panel.err());
            assertTrue(panel.out().contains("error=the Environment speaks TLS (tls=on): set ROBOSIM_KEYS to the "
                    + "simulation's keys"), panel.out());
            // with the keys, at a port of another kind: told inside TLS as without it
            try (Socket atControl = new Socket(InetAddress.getLoopbackAddress(), tlsControl.port())) {
                java.io.IOException told = org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class,
                        () -> new robosim.hardware.HardwareSimulator("robot1", null).connect(atControl, 64, keys));
                assertEquals(robosimControlRefusal(), told.getMessage());
            }
            java.io.IOException panelTold = org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class,
                    () -> new ControlClient("127.0.0.1", port, keys, ControlFixture.TIMEOUT_MS).close());
            assertEquals("the Environment gave no challenge: this is the Environment's robot port, which speaks RoboSim's "
                    + "object protocol (robots, viewers, Geometry); the Control Panel uses the control port (8100 by "
                    + "default), a browser the web port (--web-port)", panelTold.getMessage());
        } finally {
            tlsControl.close();
            tls.shutdown();
        }
    }
}
