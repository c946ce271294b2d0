package robosim.protocol;

import java.util.List;

/**
 * How much a RoboSim process logs: the log backend's level ({@code slf4j-simple}'s {@value #PROPERTY}, {@code info}
 * by default), which the scripts' {@code --quiet} ({@code warn}) and {@code --log-level LEVEL} set for the JVM they
 * start; a process that starts another JVM of RoboSim's hands it on ({@link #jvmOptions}).
 */
public final class LogLevel {
    /** The system property the log backend reads its level from. */
    public static final String PROPERTY = "org.slf4j.simpleLogger.defaultLogLevel";

    private LogLevel() {
    }

    /** The JVM option that gives a child JVM this JVM's level, if one was set; none otherwise. */
    public static List<String> jvmOptions() {
        String level = System.getProperty(PROPERTY);
        return level == null || level.isBlank() ? List.of() : List.of("-D" + PROPERTY + "=" + level);
    }
}
