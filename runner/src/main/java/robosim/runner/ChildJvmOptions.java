package robosim.runner;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Option;

/** The headless runner's JVM options for its children, per role (a picocli mixin). */
final class ChildJvmOptions {
    @Option(names = "--jvm-opt", paramLabel = "OPTION",
            description = "An option for every child JVM, after the per-role ones; repeatable.")
    List<String> all = new ArrayList<>();

    @Option(names = "--environment-jvm-opts", paramLabel = "OPTIONS", defaultValue = "-XX:+UseSerialGC",
            description = "JVM options for the Environment, space-separated (default: ${DEFAULT-VALUE}).")
    String environmentJvmOpts;

    @Option(names = "--geometry-jvm-opts", paramLabel = "OPTIONS", defaultValue = "-XX:+UseSerialGC",
            description = "JVM options for the Geometry process (default: ${DEFAULT-VALUE}).")
    String geometryJvmOpts;

    @Option(names = "--robot-jvm-opts", paramLabel = "OPTIONS",
            defaultValue = "-XX:+UseSerialGC -XX:TieredStopAtLevel=1",
            description = "JVM options for each robot process (default: ${DEFAULT-VALUE}: ten JVMs warming up "
                    + "with C1 only cost less CPU on a small machine; give '' for heavy control code).")
    String robotJvmOpts;

    @Option(names = "--profile", paramLabel = "DIR",
            description = "Record a Java Flight Recorder profile of the Environment and the Geometry process into "
                    + "DIR (environment.jfr, geometry.jfr); read them with 'jfr print' or JDK Mission Control.")
    Path profile;

    List<String> environment() throws IOException {
        return profiled(opts(environmentJvmOpts), "environment");
    }

    List<String> geometry() throws IOException {
        return profiled(opts(geometryJvmOpts), "geometry");
    }

    List<String> robot() {
        return opts(robotJvmOpts);
    }

    /** Adds a flight recording of the whole process to {@code options} when --profile is given. */
    private List<String> profiled(List<String> options, String role) throws IOException {
        if (profile == null) {
            return options;
        }
        Files.createDirectories(profile);
        List<String> withJfr = new ArrayList<>(options);
        withJfr.add("-XX:StartFlightRecording=filename=" + profile.resolve(role + ".jfr").toAbsolutePath()
                + ",settings=profile");
        return withJfr;
    }

    private static List<String> opts(String spaceSeparated) {
        return spaceSeparated == null || spaceSeparated.isBlank() ? List.of()
                : List.of(spaceSeparated.trim().split("\\s+"));
    }
}
