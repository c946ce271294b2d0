package robosim.protocol;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;

/**
 * Virtual threads where the JVM has them (JDK 21 and later), found at run time: the project builds for JDK 17. Shared
 * by the Hardware Simulator (control code) and the Environment (a one-JVM run's loop). Also the one way to reach their
 * scheduler, to give it more carrier threads ({@link #widen}).
 */
public final class VirtualThreads {
    /** The system property that sets how many carrier threads virtual threads get (the JDK's own). */
    public static final String PARALLELISM = "jdk.virtualThreadScheduler.parallelism";
    /** {@code Thread.ofVirtual()}, or null on a JVM without virtual threads. */
    private static final MethodHandle OF_VIRTUAL = ofVirtual();
    private static final MethodHandle BUILDER_NAME = builderMethod("name", MethodType.methodType(builderType(),
            String.class));
    private static final MethodHandle BUILDER_START = builderMethod("start", MethodType.methodType(Thread.class,
            Runnable.class));
    /** The JDK's class of the platform threads that carry virtual threads. */
    private static final String CARRIER = "jdk.internal.misc.CarrierThread";

    private VirtualThreads() {
    }

    /** True if this JVM has virtual threads. */
    public static boolean available() {
        return OF_VIRTUAL != null;
    }

    /** Starts {@code body} on a new virtual thread named {@code name}; only where {@link #available()}. */
    public static Thread start(String name, Runnable body) {
        if (OF_VIRTUAL == null) {
            throw new IllegalStateException("this JVM (" + Runtime.version() + ") has no virtual threads");
        }
        try {
            Object builder = OF_VIRTUAL.invoke();
            Object named = BUILDER_NAME.invoke(builder, name);
            return (Thread) BUILDER_START.invoke(named, body);
        } catch (Throwable e) {
            throw new IllegalStateException("could not start a virtual thread for " + name, e);
        }
    }

    /** True if this JVM's virtual threads run on one carrier thread (its {@link #PARALLELISM} is 1). */
    public static boolean oneCarrier() {
        return available() && "1".equals(System.getProperty(PARALLELISM, "").trim());
    }

    /**
     * Gives virtual threads one carrier thread more than they have, from a platform thread: their scheduler found
     * from one of its carriers (a {@link ForkJoinWorkerThread}), widened with {@code ForkJoinPool.setParallelism}
     * (JDK 19 and later). Returns the carriers they may now use, or -1 if there is no scheduler to widen (no virtual
     * thread has run yet, or no JDK that has the method).
     */
    public static int widen() {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t instanceof ForkJoinWorkerThread w && t.getClass().getName().equals(CARRIER)) {
                ForkJoinPool pool = w.getPool();
                try {
                    MethodHandle set = MethodHandles.publicLookup().findVirtual(ForkJoinPool.class, "setParallelism",
                            MethodType.methodType(int.class, int.class));
                    int more = pool.getParallelism() + 1;
                    set.invoke(pool, more);
                    // (the pool starts a carrier when work comes, not when it may: what waits, queued while there was
                    // no carrier to take it, is taken by the carrier this empty task brings)
                    pool.execute(() -> { });
                    return more;
                } catch (Throwable e) {
                    return -1;
                }
            }
        }
        return -1;
    }

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
