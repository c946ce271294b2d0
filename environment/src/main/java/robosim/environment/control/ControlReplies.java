package robosim.environment.control;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/** A control port's JSON replies, {@code {"ok":true,...}} or {@code {"ok":false,"error":"..."}}, and its text made safe. */
public final class ControlReplies {
    private static final ObjectMapper JSON = new ObjectMapper();

    private ControlReplies() {
    }

    public static ObjectNode ok(String message) {
        ObjectNode n = JSON.createObjectNode();
        n.put("ok", true);
        if (message != null) {
            n.put("message", message);
        }
        return n;
    }

    public static ObjectNode error(String message) {
        ObjectNode n = JSON.createObjectNode();
        n.put("ok", false);
        n.put("error", message);
        return n;
    }

    /** Network text made safe for a log line or a reply: control characters as '?', at most 40 characters. */
    public static String abbreviate(String s) {
        return abbreviate(s, 40);
    }

    public static String abbreviate(String s, int max) {
        String clean = String.valueOf(s).replaceAll("\\p{Cntrl}", "?");
        return clean.length() > max ? clean.substring(0, max) + "..." : clean;
    }

    /** A positive whole number from a request ({@code what} names it in the error). */
    public static long positive(String what, String arg) {
        try {
            long n = Long.parseLong(arg);
            if (n < 1) {
                throw new NumberFormatException();
            }
            return n;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + " needs a positive whole number, got \"" + abbreviate(arg) + "\"");
        }
    }
}
