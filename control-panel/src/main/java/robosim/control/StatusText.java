package robosim.control;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The Control Panel's status lines, from one {@code status} reply: a headline (state, step, and the
 * steps per second only while running) and the details (file, robots, who is connected and who has
 * left, where geometry is resolved, why the run ended; for a replay, the recording's steps, the speed and
 * the viewers; each robot's state when it is held, waited for, returning or gone). Values from the network are shown with
 * control characters replaced and long values cut, so a hostile reply cannot garble the window.
 */
final class StatusText {
    private static final int MAX_VALUE = 200;

    private StatusText() {
    }

    static String headline(JsonNode status) {
        String state = clean(status.path("state").asText("?"));
        String head = state + "   step " + status.path("step").asLong();
        if (state.equals("RUNNING")) {
            head += String.format(Locale.ROOT, "   %.1f steps/s", status.path("steps_per_s").asDouble());
        }
        return head;
    }

    static String details(JsonNode status) {
        if (status.path("replay").asBoolean(false)) {
            return "replaying: " + clean(status.path("file").asText()) + "\nrecorded:  steps "
                    + status.path("first_step").asLong() + " to " + status.path("last_step").asLong()
                    + (status.path("at_end").asBoolean() ? " (at the end: seek, or stop)" : "")
                    + "\nspeed:     x" + status.path("speed").asDouble() + "\nviewers:   " + status.path("viewers").asInt();
        }
        return "file:      " + clean(status.path("file").asText()) + "\nrobots:    " + robots(status)
                + "\nconnected: " + list(status.path("connected")) + "\nleft:      " + list(status.path("left"))
                + "\ngeometry:  " + clean(status.path("geometry").asText("?"))
                + (status.has("reason") ? "\nended:     " + clean(status.path("reason").asText()) : "");
    }

    /** Each robot with its state where it is not the plain one ("ring2 held since 1001"), else the names. */
    private static String robots(JsonNode status) {
        if (!status.has("robot_states")) {
            return list(status.path("robots"));
        }
        StringBuilder b = new StringBuilder();
        for (JsonNode r : status.path("robot_states")) {
            String state = clean(r.path("state").asText());
            b.append(b.length() == 0 ? "" : ", ").append(clean(r.path("name").asText()));
            if (!state.equals("running") && !state.equals("connected")) {
                b.append(' ').append(state).append(r.has("since") ? " since " + r.path("since").asLong() : "");
            }
        }
        return b.length() == 0 ? "-" : b.toString();
    }

    /** The robots a remove may name: those in the run now (running, held, waiting or returning) and those added not yet there. */
    static List<String> removable(JsonNode status) {
        List<String> names = new ArrayList<>();
        for (JsonNode r : status.path("robot_states")) {
            String state = r.path("state").asText();
            if (List.of("running", "held", "waiting", "returning", "added").contains(state)) {
                names.add(clean(r.path("name").asText()));
            }
        }
        return names;
    }

    private static String list(JsonNode array) {
        StringBuilder b = new StringBuilder();
        for (JsonNode n : array) {
            b.append(b.length() == 0 ? "" : ", ").append(clean(n.asText()));
        }
        return b.length() == 0 ? "-" : b.toString();
    }

    private static String clean(String value) {
        String s = value.replaceAll("\\p{Cntrl}", "?");
        return s.length() > MAX_VALUE ? s.substring(0, MAX_VALUE) + "..." : s;
    }
}
