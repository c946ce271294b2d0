package robosim.environment.core;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A world's experiment code ({@code <loopFunctions class="..."> <param name= value=/> </loopFunctions>}): the class
 * of its {@link robosim.loop.LoopFunctions}, looked up where control classes are
 * ({@link robosim.protocol.ControlClasses}), or a Python script ({@code python:PATH}, {@link LoopScript}), and its
 * parameters, in file order; or an instance made already, which a
 * run uses instead of a new one of its class (a test's, {@code robosim.testkit.Simulation.Builder#loopFunctions}).
 *
 * @param given the instance to run, or null: a new instance of the class for each run
 */
public record LoopSpec(String className, Map<String, String> parameters, robosim.loop.LoopFunctions given) {
    /** The name the loop functions' messages to robots come from, which no robot of their world may have. */
    public static final String SENDER = "loop";

    public LoopSpec {
        java.util.Objects.requireNonNull(className, "className");
        parameters = Collections.unmodifiableMap(new LinkedHashMap<>(parameters));
    }

    /** A class's, a new instance for each run. */
    public LoopSpec(String className, Map<String, String> parameters) {
        this(className, parameters, null);
    }

    /**
     * Why {@code className} cannot be loop functions on this thread's class path (the class is not initialised), or
     * why its script cannot run ({@code python:PATH}: no such file), or null.
     */
    public static String problem(String className) {
        if (robosim.protocol.ControlScripts.isScript(className)) {
            return robosim.protocol.ControlScripts.problem(className);
        }
        Class<?> c;
        try {
            c = Class.forName(className, false, robosim.protocol.ControlClasses.loader());
        } catch (ClassNotFoundException | LinkageError e) {
            return "there is no class " + className + " on the class path (a class of your own: --classpath or "
                    + "ROBOSIM_CLASSPATH)";
        }
        if (!robosim.loop.LoopFunctions.class.isAssignableFrom(c)) {
            return className + " does not implement " + robosim.loop.LoopFunctions.class.getName();
        }
        return null;
    }
}
