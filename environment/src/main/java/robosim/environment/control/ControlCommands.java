package robosim.environment.control;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * What a control port serves once a caller has proved the shared secret: the Environment's requests
 * ({@link EnvironmentCommands}) or a replay's ({@code robosim.environment.replay.ReplayCommands}). Called
 * by the control threads, one request of a connection at a time; a reply is {@link ControlReplies#ok} or
 * {@link ControlReplies#error}.
 */
public interface ControlCommands {
    /** True for the requests that may wait: they run on the {@code control} thread, the rest on {@code control-quick}. */
    boolean waits(String verb);

    /**
     * The reply to {@code verb arg} ({@code verb} lower case, {@code arg} stripped, perhaps empty).
     *
     * @throws IllegalArgumentException for a bad argument (its message is the reply's error)
     */
    ObjectNode handle(String verb, String arg) throws Exception;

    /** The requests it knows, for the reply to an unknown one. */
    String known();
}
