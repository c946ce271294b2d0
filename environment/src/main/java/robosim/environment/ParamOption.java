package robosim.environment;

import java.util.LinkedHashMap;
import java.util.Map;
import picocli.CommandLine.Option;

/** Values of an environment file's parameters (a picocli mixin of every command line that loads a world). */
public final class ParamOption {
    @Option(names = "--param", paramLabel = "NAME=VALUE", description = "Give the environment file's parameter NAME "
            + "(a placeholder $${NAME:default} in it, or a <param name=\"NAME\"> of the world) this value; repeat for "
            + "more. A name the file does not have is refused (test-envs/README.md).")
    private Map<String, String> values = new LinkedHashMap<>();

    /** Each parameter given, in order. */
    public Map<String, String> values() {
        return values;
    }
}
