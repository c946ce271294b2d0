package robosim.protocol;

/**
 * Where a robot's control class is found: the context class loader of the thread that asks (a warm JVM gives each
 * run a loader of its own, {@code robosim.runner.ControlClassLoader}, as its threads' context loader), else the class
 * path's. The one rule for every part that looks a control class up: the Hardware Simulator that makes one, the
 * Environment and the headless runner that check one before a run.
 */
public final class ControlClasses {
    private ControlClasses() {
    }

    /** The loader control classes come from on this thread. */
    public static ClassLoader loader() {
        ClassLoader context = Thread.currentThread().getContextClassLoader();
        return context != null ? context : ControlClasses.class.getClassLoader();
    }
}
