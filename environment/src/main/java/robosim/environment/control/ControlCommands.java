package robosim.environment.control;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.stream.Collectors;

/**
 * What a control port serves once a caller has proved the shared secret: the Environment's requests
 * ({@link EnvironmentCommands}) or a replay's ({@code robosim.environment.replay.ReplayCommands}), each a
 * {@link ControlVerb} declared once. Called by the control threads, one request of a connection at a time; a
 * reply is {@link ControlReplies#ok} or {@link ControlReplies#error}.
 */
public interface ControlCommands {
    /** Every request it serves, in the order they are listed. */
    List<ControlVerb> verbs();

    /** The request {@code verb} (lower case) names, or null. */
    default ControlVerb verb(String verb) {
        for (ControlVerb v : verbs()) {
            if (v.answers(verb)) {
                return v;
            }
        }
        return null;
    }

    /** True for the requests that may wait: they run on the {@code control} thread, the rest on {@code control-quick}. */
    default boolean waits(String verb) {
        ControlVerb v = verb(verb);
        return v != null && v.waits();
    }

    /**
     * The reply to {@code verb arg} ({@code verb} lower case, {@code arg} stripped, perhaps empty); null for a
     * request it does not serve.
     *
     * @throws IllegalArgumentException for a bad argument (its message is the reply's error)
     */
    default ObjectNode handle(String verb, String arg) throws Exception {
        ControlVerb v = verb(verb);
        return v == null ? null : v.handler().handle(arg);
    }

    /** The requests it serves, for the reply to an unknown one. */
    default String known() {
        return verbs().stream().map(ControlVerb::usage).collect(Collectors.joining(", "));
    }
}
