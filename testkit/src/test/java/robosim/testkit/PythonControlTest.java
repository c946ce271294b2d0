package robosim.testkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * A testkit simulation of a world whose robots are Python scripts ({@code control="python:bounce.py"}): the testkit
 * starts them as any layout does, and they move as the same robot in Java does. Needs {@code ROBOSIM_PYTHON}, a
 * Python with the package in {@code python/} installed ({@code .ci/run} sets it); skipped, saying so, without it.
 */
class PythonControlTest {
    private static final Path BOUNCE = Path.of("../examples/python/bounce.xml");
    private static final int STEPS = 200;
    /** How long a robot may take over a step: four interpreters starting at once on a loaded machine, generously. */
    private static final Duration START = Duration.ofMinutes(5);

    @Test
    void aWorldOfPythonRobotsRunsInATestAsTheSameRobotsInJava() {
        String python = System.getenv("ROBOSIM_PYTHON");
        Assumptions.assumeTrue(python != null && !python.isBlank(),
                "ROBOSIM_PYTHON is not set: the testkit's run of Python robots is skipped");
        Map<String, Pose> java = new LinkedHashMap<>();
        try (Simulation s = Simulation.of(BOUNCE).param("control", "robosim.examples.Bounce").stepTimeout(START)
                .start()) {
            s.run(STEPS);
            s.robots().forEach(r -> java.put(r, s.pose(r)));
        }
        try (Simulation s = Simulation.of(BOUNCE).stepTimeout(START).start()) {
            s.run(STEPS);
            for (String r : s.robots()) {
                assertEquals(java.get(r), s.pose(r), r + " moved otherwise in Python than in Java");
            }
            assertTrue(s.reported("b1", "turns") != null && s.reported("b1", "turns") > 0,
                    "b1 turned, and reported it: " + s.reports("b1"));
        }
    }
}
