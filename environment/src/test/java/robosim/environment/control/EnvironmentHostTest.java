package robosim.environment.control;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.environment.run.Departure;
import robosim.environment.run.RunSummary;

/** The Environment's exit code from how its run went. */
class EnvironmentHostTest {
    private static RunSummary run(boolean completed, List<Departure> departures) {
        return new RunSummary(100, 3, 1.0, completed ? "completed 100 steps" : "the Geometry process was lost",
                completed, 0, 0, 0, departures.size(), 0, 0, departures, false);
    }

    @Test
    void aRunWhoseLoopFunctionsThrewExits4() {
        RunSummary failed = new RunSummary(7, 3, 1.0, "loop functions X failed in postStep at step 7: boom", false,
                0, 0, 0, 0, 0, 0, List.of(), true);
        assertEquals(EnvironmentHost.EXIT_CONTROL_FAILED, EnvironmentHost.exitCode(failed));
    }

    @Test
    void aCompletedRunThatLostARobotExits3() {
        assertEquals(0, EnvironmentHost.exitCode(run(true, List.of())));
        assertEquals(EnvironmentHost.EXIT_ROBOTS_REMOVED,
                EnvironmentHost.exitCode(run(true, List.of(new Departure("r2", 40, "step timeout")))));
        assertEquals(1, EnvironmentHost.exitCode(run(false, List.of(new Departure("r2", 40, "step timeout")))));
    }
}
