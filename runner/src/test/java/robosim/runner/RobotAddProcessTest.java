package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.control.ControlClient;

/**
 * The control port's {@code add} on an Environment started with {@code --launch-robots} (as headless.sh
 * starts it): the Environment starts the new robot's process, which joins the held run at the pose given and
 * takes part from the next step; its output and exit go to the Environment's log.
 */
class RobotAddProcessTest {
    private static final long LONG_S = 60;

    private static ProcessLines java(String name, String... args) throws Exception {
        return new ProcessLines(name, new ProcessBuilder(ProcessLines.java(List.of(), args[0],
                java.util.Arrays.copyOfRange(args, 1, args.length))));
    }

    @Test
    void addStartsTheRobotsProcessAndItJoinsAtItsPose() throws Exception {
        try (ProcessLines env = java("environment", "robosim.environment.EnvironmentMain",
                "src/test/resources/three-robots.xml", "--steps", "400", "--no-geometry", "--robot-port", "0",
                "--viewer-port", "0", "--control-port", "0", "--start-paused", "--launch-robots")) {
            Map<String, String> ports = HeadlessRunner.fields(env.await("listening robots=", LONG_S));
            try (ProcessLines others = java("r1,2,3", "robosim.hardware.MultiRobotMain", "127.0.0.1", ports.get("robots"),
                    "--robot", "r1:ArRobot:robosim.examples.BackAndForth", "--robot",
                    "r2:ArRobot:robosim.examples.BackAndForth", "--robot", "r3:Scout:robosim.examples.BackAndForth");
                    ControlClient control = new ControlClient("127.0.0.1", Integer.parseInt(ports.get("control")), null,
                            (int) TimeUnit.SECONDS.toMillis(LONG_S))) {
                env.await("running robots=3", LONG_S);
                assertEquals("paused at step 10", ControlFixture.ok(control, "step 10"));
                JsonNode noSuch = control.request("add w10 Scout 1.0 3.5 0 no.such.Class");
                assertTrue(noSuch.path("error").asText().startsWith("add w10: there is no class no.such.Class on the "
                        + "class path its robot process would run with"), noSuch.toString());
                JsonNode notControl = control.request("add w11 Scout 1.0 3.5 0 java.lang.String");
                assertEquals("add w11: java.lang.String is not a RobotControl", notControl.path("error").asText());
                assertEquals("w10 w11 not in the list", java.util.stream.StreamSupport.stream(
                        control.request("robots").path("robots").spliterator(), false)
                        .anyMatch(r -> r.path("name").asText().startsWith("w1")) ? "listed" : "w10 w11 not in the list");
                ControlFixture.ok(control, "pause");
                assertEquals("added r9 and started its robot process (robosim.examples.BackAndForth)",
                        ControlFixture.ok(control, "add r9 Scout 11 2 180 robosim.examples.BackAndForth"));
                env.await("robot r9 added from the control port: a Scout at (11000, 2000) mm heading 180.0 deg", LONG_S);
                env.await("robot r9 joins at (11000, 2000) mm heading 180.0 deg", LONG_S); // (to the mm)
                JsonNode r9 = control.request("robots").path("robots").get(3);
                assertEquals("r9 joining", r9.path("name").asText() + " " + r9.path("state").asText());
                ControlFixture.ok(control, "resume");
                env.await("robot r9 takes part from step 12", LONG_S);
                env.await("summary steps=400", LONG_S);
                env.await("robot r9's process exited (0)", LONG_S);
                assertTrue(others.process.waitFor(LONG_S, TimeUnit.SECONDS));
            }
            assertTrue(env.process.waitFor(LONG_S, TimeUnit.SECONDS));
            assertEquals(0, env.process.exitValue(), env.output());
        }
    }
}
