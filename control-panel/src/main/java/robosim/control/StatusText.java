package robosim.control;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Locale;

/**
 * The Control Panel's status lines, from one {@code status} reply: a headline (state, step, and the
 * steps per second only while running) and the details (file, robots, who is connected and who has
 * left, where geometry is resolved, why the run ended; for a replay, the recording's steps, the speed and
 * the viewers). Values from the network are shown with
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
        return "file:      " + clean(status.path("file").asText()) + "\nrobots:    " + list(status.path("robots"))
                + "\nconnected: " + list(status.path("connected")) + "\nleft:      " + list(status.path("left"))
                + "\ngeometry:  " + clean(status.path("geometry").asText("?"))
                + (status.has("reason") ? "\nended:     " + clean(status.path("reason").asText()) : "");
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
