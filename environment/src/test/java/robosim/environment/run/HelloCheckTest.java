package robosim.environment.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.environment.core.JoinRule;
import robosim.environment.core.LoopSpec;
import robosim.environment.core.WorldSpec;
import robosim.environment.core.WorldSpec.RobotSpec;
import robosim.protocol.Arena;
import robosim.protocol.RobotHello;

/**
 * A hello's check: a robot that would join a world with loop functions under their messages' name, {@code loop}, is
 * refused, whatever rule would let it join (the file's reader refuses such a rule and such a robot already; a rule
 * made otherwise, the control port's, must not let one in); the same hello joins a world without them.
 */
class HelloCheckTest {
    private static final RobotSpec LOOP = new RobotSpec("loop", "ArRobot", "", 4000, 4000, 0);
    private static final WorldSpec WORLD = new WorldSpec("mem", "hellos", 500, 1, new Arena(0, 0, 20_000, 20_000),
            List.of(), List.of(new RobotSpec("a", "ArRobot", "", 2000, 2000, 0)), 0, 8192, List.of(),
            WorldSpec.DEFAULT_TAG_RANGE_MM, java.util.Set.of(), List.of(new JoinRule("loop", LOOP, null, 1)));

    private static RobotHello hello(String name) {
        return new RobotHello(name, robosim.devices.RobotTypes.properties("ArRobot"));
    }

    @Test
    void aJoinerNamedLoopIsRefusedOnlyWhereTheWorldHasLoopFunctions() {
        WorldSpec withLoop = WORLD.withLoopFunctions(new LoopSpec("robosim.examples.ForagingLoopFunctions", Map.of()));
        HelloCheck.Checked refused = new HelloCheck(withLoop).admit(hello("loop"));
        assertEquals("\"loop\" is the name the world's loop functions' messages come from: no robot of it may have it",
                refused.refusal());
        assertNull(refused.hello());
        HelloCheck.Checked joined = new HelloCheck(WORLD).admit(hello("loop"));
        assertNull(joined.refusal(), joined.refusal());
        assertNotNull(joined.hello());
    }
}
