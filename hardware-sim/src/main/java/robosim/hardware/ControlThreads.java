package robosim.hardware;

import java.util.Locale;
import robosim.protocol.VirtualThreads;

/**
 * Where control code runs: on a virtual thread when the JVM offers them (JDK 21 and later: a wake costs
 * a hand-off inside the JVM, not one of the operating system's), else on a platform thread, the only kind
 * JDK 17 has. The project builds for JDK 17, so the virtual kind is found by name at run time. The system
 * property {@code robosim.controlThreads} ({@code virtual} or {@code platform}) chooses; a robot's steps
 * do not depend on the kind (the control code and the exchange take turns, see {@link ControlLink}).
 * Control code that computes for long without calling the robot keeps its carrier thread (one per core)
 * busy meanwhile, where a platform thread would be time-sliced: such code wants {@code platform}.
 */
final class ControlThreads {
    private static final boolean VIRTUAL = VirtualThreads.available()
            && !"platform".equals(System.getProperty("robosim.controlThreads", "").toLowerCase(Locale.ROOT));

    private ControlThreads() {
    }

    /** The kind this process runs control code on: "virtual" or "platform". */
    static String kind() {
        return VIRTUAL ? "virtual" : "platform";
    }

    /** What this process runs on, for its first lines: the JVM (and the scripts' reason for it) and the thread kind. */
    static String describe() {
        String choice = System.getenv("ROBOSIM_JAVA_CHOICE");
        return "Java " + Runtime.version() + (choice == null ? "" : " from " + choice) + "; control code on "
                + kind() + " threads";
    }

    /** Starts {@code body} on a new thread of this process's kind, named {@code name}. */
    static Thread start(String name, Runnable body) {
        if (VIRTUAL) {
            return VirtualThreads.start(name, body);
        }
        Thread t = new Thread(body, name);
        t.setDaemon(true);
        t.start();
        return t;
    }
}
