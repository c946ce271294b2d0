package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

class ParameterUseTest {
    @Test
    void aNameNotGivenIsSaidOnceForEveryRobotThatAskedWithTheNamesGiven() {
        Map<String, Set<String>> asked = new LinkedHashMap<>();
        asked.put("w1", Set.of("repel_m", "speed"));
        asked.put("w2", Set.of("repel_m", "speed"));
        Map<String, Set<String>> given = Map.of("w1", Set.of("repel_mm", "speed"), "w2", Set.of("repel_mm", "speed"));
        assertEquals(List.of("parameter \"repel_m\" asked for by the control code of w1, w2 is not given to them (its "
                + "default was used); given: repel_mm, speed"), ParameterUse.warnings(asked, given, null, Map.of()),
                "a robot process sees its own robots only: no word of what nothing asked for");
        assertEquals(List.of("parameter \"repel_m\" asked for by the control code of w1, w2 is not given to them (its "
                + "default was used); given: repel_mm, speed", "parameter \"repel_mm\" of the world was asked for by no "
                + "robot's control code; asked: repel_m, speed"),
                ParameterUse.warnings(asked, given, Set.of("repel_mm", "speed"), Map.of()));
    }

    @Test
    void everyParameterAskedForIsNoWarningAndARobotsOwnNotAskedForIs() {
        Map<String, Set<String>> asked = Map.of("a", Set.of("speed", "role"), "b", Set.of("speed"));
        Map<String, Set<String>> given = Map.of("a", Set.of("speed", "role"), "b", Set.of("speed", "role"));
        assertEquals(List.of(), ParameterUse.warnings(asked, given, Set.of("speed"), Map.of("a", Set.of("role"))));
        assertEquals(List.of("parameter \"role\" of robot b was not asked for by its control code; it asked: speed"),
                ParameterUse.warnings(asked, given, Set.of("speed"), Map.of("a", Set.of("role"), "b", Set.of("role"))));
        assertEquals(List.of(), ParameterUse.warnings(Map.of("a", Set.of()), Map.of("a", Set.of()), Set.of(),
                Map.of()), "a world without parameters, control code that asks none");
    }
}
