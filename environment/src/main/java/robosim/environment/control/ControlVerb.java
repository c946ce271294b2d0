package robosim.environment.control;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.Locale;

/**
 * One control-port request, declared once, where it is served: its name and the words it takes ({@link #usage},
 * {@code step N}), which thread answers it ({@link #waits}: one that may wait runs on the {@code control} thread, one
 * at a time; the others on {@code control-quick}, at once even while another connection's request waits), what it
 * does ({@link #help}), and its handler; other names it answers to ({@link #aliases}) are not listed. A set of them
 * is a {@link ControlCommands}; the reply to an unknown request lists them, and a test holds the Control Panel's
 * help and the protocol's table of requests to them.
 *
 * @param handler the reply to the request, given its argument (stripped, perhaps empty); an
 *     {@link IllegalArgumentException}'s message is the reply's error
 */
public record ControlVerb(String name, String usage, boolean waits, String help, Handler handler, List<String> aliases) {
    /** What a request does: its reply. */
    public interface Handler {
        ObjectNode handle(String arg) throws Exception;
    }

    /** A request answered at once, on {@code control-quick}. {@code usage}: its name, then the words it takes. */
    public static ControlVerb quick(String usage, String help, Handler handler) {
        return new ControlVerb(nameOf(usage), usage, false, help, handler, List.of());
    }

    /** A request that may wait (for steps, the loop, a new simulation), on the {@code control} thread. */
    public static ControlVerb waiting(String usage, String help, Handler handler) {
        return new ControlVerb(nameOf(usage), usage, true, help, handler, List.of());
    }

    /** The same request, answering to {@code names} too. */
    public ControlVerb alias(String... names) {
        return new ControlVerb(name, usage, waits, help, handler, List.of(names));
    }

    /** True if {@code verb} (lower case) names this request. */
    public boolean answers(String verb) {
        return name.equals(verb) || aliases.contains(verb);
    }

    private static String nameOf(String usage) {
        return usage.split(" ", 2)[0].toLowerCase(Locale.ROOT);
    }
}
