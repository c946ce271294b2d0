package robosim.environment.core;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The parameters an environment file gives its robots' control code ({@code <param name= value=>}): the
 * world's, for every robot, and each robot's own, over the world's. Immutable; in file order.
 *
 * @param world the {@code <param>}s of {@code <environment>}
 * @param robots each robot's own {@code <param>}s, by robot name (robots without any are not here)
 */
public record Parameters(Map<String, String> world, Map<String, Map<String, String>> robots) {
    /** A world without parameters. */
    public static final Parameters NONE = new Parameters(Map.of(), Map.of());

    public Parameters {
        world = ordered(world);
        Map<String, Map<String, String>> each = new LinkedHashMap<>();
        robots.forEach((robot, own) -> each.put(robot, ordered(own)));
        robots = Collections.unmodifiableMap(each);
    }

    private static Map<String, String> ordered(Map<String, String> m) {
        return Collections.unmodifiableMap(new LinkedHashMap<>(m));
    }

    /** What robot {@code name}'s control code gets: the world's parameters with its own over them. */
    public Map<String, String> of(String name) {
        Map<String, String> own = robots.get(name);
        if (own == null || own.isEmpty()) {
            return world;
        }
        Map<String, String> all = new LinkedHashMap<>(world);
        all.putAll(own);
        return Collections.unmodifiableMap(all);
    }

    /**
     * The warnings at a run's end, one line each ({@link robosim.protocol.ParameterUse}), from what each robot's
     * control code asked for ({@code asked}, by robot: every robot of the run): names asked for and not given, and
     * parameters of the world or of a robot nothing asked for.
     */
    public java.util.List<String> warnings(Map<String, java.util.Set<String>> asked) {
        Map<String, java.util.Set<String>> given = new LinkedHashMap<>();
        Map<String, java.util.Set<String>> own = new LinkedHashMap<>();
        for (String robot : asked.keySet()) {
            given.put(robot, of(robot).keySet());
            own.put(robot, robots.getOrDefault(robot, Map.of()).keySet());
        }
        return robosim.protocol.ParameterUse.warnings(asked, given, world.keySet(), own);
    }
}
