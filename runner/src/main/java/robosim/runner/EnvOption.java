package robosim.runner;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/** The environment file a runner runs (a picocli mixin of headless.sh and learning-host.sh). */
public final class EnvOption {
    @Option(names = "--env", required = true, paramLabel = "FILE.xml", description = "The environment file.")
    private Path file;

    public Path file() {
        return file;
    }
}
