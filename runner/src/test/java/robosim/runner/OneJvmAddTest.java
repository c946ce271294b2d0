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
 * An Environment started with {@code --one-jvm} runs its file's robots in its own JVM, with no robot process and
 * no Geometry process; the control port's {@code add ... CONTROL} starts the new robot in that JVM too, and one
 * whose control class this JVM does not have is refused before anything is added.
 */
class OneJvmAddTest {
    private static final long LONG_S = 60;

    @Test
    void theFilesRobotsRunInItsJvmAndAnAddedRobotStartsThere() throws Exception {
        List<String> command = ProcessLines.java(List.of(), "robosim.environment.EnvironmentMain",
                "src/test/resources/three-robots.xml", "--one-jvm", "--steps", "400", "--robot-port", "0",
                "--viewer-port", "0", "--control-port", "0", "--start-paused");
        try (ProcessLines env = new ProcessLines("environment", new ProcessBuilder(command))) {
            Map<String, String> ports = HeadlessRunner.fields(env.await("listening robots=", LONG_S));
            assertEquals("-1", ports.get("geometry"), "collision and sonar run in the Environment");
            try (ControlClient control = new ControlClient("127.0.0.1", Integer.parseInt(ports.get("control")), null,
                    (int) TimeUnit.SECONDS.toMillis(LONG_S))) {
                env.await("running robots=3", LONG_S);
                assertEquals("paused at step 10", ControlFixture.ok(control, "step 10"));
                JsonNode noSuch = control.request("add w10 Scout 1.0 3.5 0 no.such.Class");
                assertEquals("add w10: there is no class no.such.Class on the class path this Environment runs with (a "
                        + "class of your own: --classpath or ROBOSIM_CLASSPATH)", noSuch.path("error").asText());
                assertEquals("added r9 and started it in this JVM (robosim.examples.BackAndForth)",
                        ControlFixture.ok(control, "add r9 Scout 11 2 180 robosim.examples.BackAndForth"));
                env.await("robot r9 joins at (11000, 2000) mm heading 180.0 deg", LONG_S);
                ControlFixture.ok(control, "resume");
                // (the 11th step is being collected while the run holds: r9 takes part from it if its hello came
                // before every request of it was in, else from the 12th; both are legal)
                String from = env.await("robot r9 takes part from step ", LONG_S);
                assertTrue(from.endsWith("from step 11") || from.endsWith("from step 12"), from);
                env.await("summary steps=400 robots=4", LONG_S);
            }
            assertTrue(env.process.waitFor(LONG_S, TimeUnit.SECONDS));
            assertEquals(0, env.process.exitValue(), env.output());
        }
    }
}
