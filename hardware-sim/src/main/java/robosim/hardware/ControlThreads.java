package robosim.hardware;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.util.Locale;

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
    /** {@code Thread.ofVirtual()}, or null on a JVM without virtual threads. */
    private static final MethodHandle OF_VIRTUAL = ofVirtual();
    private static final boolean VIRTUAL = OF_VIRTUAL != null
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
            try {
                Object builder = OF_VIRTUAL.invoke();
                Object named = BUILDER_NAME.invoke(builder, name);
                return (Thread) BUILDER_START.invoke(named, body);
            } catch (Throwable e) {
                throw new IllegalStateException("could not start a virtual thread for " + name, e);
            }
        }
        Thread t = new Thread(body, name);
        t.setDaemon(true);
        t.start();
        return t;
    }

    private static final MethodHandle BUILDER_NAME = builderMethod("name", MethodType.methodType(builderType(),
            String.class));
    private static final MethodHandle BUILDER_START = builderMethod("start", MethodType.methodType(Thread.class,
            Runnable.class));

    private static MethodHandle ofVirtual() {
        if (Runtime.version().feature() < 21) {
            return null; // (JDK 19 and 20 have them as a preview, usable only with --enable-preview)
        }
        try {
            Class<?> type = Class.forName("java.lang.Thread$Builder$OfVirtual");
            return MethodHandles.publicLookup().findStatic(Thread.class, "ofVirtual", MethodType.methodType(type));
        } catch (ReflectiveOperationException e) {
            return null;
        }
    }

    private static Class<?> builderType() {
        try {
            return Class.forName("java.lang.Thread$Builder");
        } catch (ClassNotFoundException e) {
            return Object.class;
        }
    }

    private static MethodHandle builderMethod(String method, MethodType type) {
        if (OF_VIRTUAL == null) {
            return null;
        }
        try {
            return MethodHandles.publicLookup().findVirtual(builderType(), method, type);
        } catch (ReflectiveOperationException e) {
            return null;
        }
    }
}
