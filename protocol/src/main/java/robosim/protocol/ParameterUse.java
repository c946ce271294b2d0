package robosim.protocol;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * Which parameters robots' control code asked for ({@code Robot.parameter}) against those the world gave them: the
 * warnings said once at a run's end, so that a mistyped name ({@code repel_m} where the world gives {@code repel_mm})
 * does not pass silently as its default.
 */
public final class ParameterUse {
    private ParameterUse() {
    }

    /**
     * One line each: a name some robots' control code asked for that they were not given (it got its default), with
     * the names they were given; and, with {@code world} (the world's own parameters, given to every robot; null when
     * not every robot's asks are seen, as in a robot process), each of the world's parameters and each robot's own
     * that no control code asked for, with the names asked.
     *
     * @param asked each robot's asked names, by robot
     * @param given each robot's parameters (the world's and its own), by robot
     * @param own each robot's own parameters (on its {@code <robot>}), by robot; may be empty
     */
    public static List<String> warnings(Map<String, Set<String>> asked, Map<String, Set<String>> given,
            Set<String> world, Map<String, Set<String>> own) {
        List<String> lines = new ArrayList<>();
        Map<String, Set<String>> unknown = new TreeMap<>(); // name -> robots that asked for it, not given it
        Set<String> known = new TreeSet<>();
        asked.forEach((robot, names) -> {
            Set<String> has = given.getOrDefault(robot, Set.of());
            for (String name : names) {
                if (!has.contains(name)) {
                    unknown.computeIfAbsent(name, n -> new TreeSet<>()).add(robot);
                    known.addAll(has);
                }
            }
        });
        unknown.forEach((name, robots) -> lines.add("parameter \"" + Printable.of(name, 100) + "\" asked for by the "
                + "control code of " + list(robots, 5) + " is not given to " + (robots.size() == 1 ? "it" : "them")
                + " (its default was used); given: " + (known.isEmpty() ? "none" : list(known, 20))));
        if (world == null) {
            return lines;
        }
        Set<String> anyAsked = new TreeSet<>();
        asked.values().forEach(anyAsked::addAll);
        for (String name : new TreeSet<>(world)) {
            if (!anyAsked.contains(name)) {
                lines.add("parameter \"" + Printable.of(name, 100) + "\" of the world was asked for by no robot's "
                        + "control code; asked: " + (anyAsked.isEmpty() ? "none" : list(anyAsked, 20)));
            }
        }
        Map<String, Set<String>> ownSorted = new LinkedHashMap<>(own);
        ownSorted.forEach((robot, names) -> {
            Set<String> its = asked.getOrDefault(robot, Set.of());
            for (String name : new TreeSet<>(names)) {
                if (!world.contains(name) && !its.contains(name)) {
                    lines.add("parameter \"" + Printable.of(name, 100) + "\" of robot " + Printable.of(robot, 100)
                            + " was not asked for by its control code; it asked: "
                            + (its.isEmpty() ? "none" : list(its, 20)));
                }
            }
        });
        return lines;
    }

    private static String list(Set<String> names, int most) {
        List<String> shown = names.stream().limit(most).map(n -> Printable.of(n, 100)).toList();
        return String.join(", ", shown) + (names.size() > most ? ", ... (" + names.size() + " in all)" : "");
    }
}
