package robosim.environment.core;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;
import robosim.protocol.StepRequest;

/** The tag ACTION: nearest thing in front, within range of the rim; taggable obstacles; the record of tags. */
class TagsTest {
    private static InProcessSteps world(double bX, Set<String> taggable) {
        // a at (1, 1) m facing +x; b ahead on the same line; c straight to a's left, 0.6 m rim to rim
        List<WorldSpec.RobotSpec> robots = List.of(new WorldSpec.RobotSpec("a", "ArRobot", "", 1000, 1000, 0),
                new WorldSpec.RobotSpec("b", "ArRobot", "", bX, 1000, 0),
                new WorldSpec.RobotSpec("c", "ArRobot", "", 1000, 2100, 0));
        List<ObstacleShape> obstacles = List.of(ObstacleShape.rectangle("flag", 1700, 1300, 100, 100));
        WorldSpec spec = new WorldSpec("mem", "t", 500, 1, new Arena(0, 0, 10_000, 10_000), obstacles, robots, 0,
                8192, List.of(), 1000, taggable);
        return InProcessSteps.of(spec, List.of(robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("ArRobot"),
                robosim.devices.RobotTypes.properties("ArRobot")));
    }

    private static String tagOnce(InProcessSteps core) throws Exception {
        core.step(0, new StepRequest[] {new StepRequest(0, 0, 0, false, List.of(), List.of(), true), null, null});
        return core.response(0).tagged();
    }

    @Test
    void tagsTheNearestThingInFrontWithinRange() throws Exception {
        // b's rim is 2100 - 250 - 250 - 1000 = 600 mm from a's: in range; c is 600 mm away too, but at 90 degrees
        InProcessSteps core = world(2100, Set.of());
        assertEquals("b", tagOnce(core));
        assertEquals(List.of("a>b"), core.tags());
        assertEquals(List.of("a>b"), core.viewerUpdate().tags(), "viewers are told");
    }

    @Test
    void nothingWhenTheNearestInFrontIsOutOfRange() throws Exception {
        // b's rim 1100 mm away, beyond the 1000 mm range; the flag is not taggable
        InProcessSteps core = world(2600, Set.of());
        assertEquals("", tagOnce(core));
        assertEquals(List.of(), core.tags());
    }

    @Test
    void aTaggableObstacleNearerThanTheRobotIsTagged() throws Exception {
        // the flag's nearest point (1.7, 1.3) m is 26.6 degrees left of a's heading, 670.8 - 250 = 420.8 mm
        // from its rim: nearer than b at 600 mm
        assertEquals("flag", tagOnce(world(2100, Set.of("flag"))));
    }
}
