package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * Two runs of the maze (noisy sonar, seed 42) give identical pose logs, byte for byte, whatever the robots'
 * connection and thread kind: once as separate processes (a socket each, control code on platform threads,
 * this JVM's JDK), once in one process over one shared connection on the newest JDK 21+ this machine has,
 * with control code on virtual threads (on a machine with no JDK 21+, on this JVM's platform threads: the
 * connection modes alone are compared then, and the test says so).
 */
class SameSeedSameRunTest {
    private static final String[] RUN = {"--env", "../test-envs/maze.xml", "--steps", "300", "--timeout-s", "120"};

    @TempDir
    Path dir;

    @Test
    void theSameSeedGivesTheSamePoseLogOverEitherConnectionAndThreadKind() throws Exception {
        Path perRobot = dir.resolve("per-robot.csv");
        List<String> args = new ArrayList<>(List.of(RUN));
        args.addAll(List.of("--pose-log", perRobot.toString()));
        assertEquals(0, new CommandLine(new HeadlessRunner()).execute(args.toArray(String[]::new)));

        Path shared = dir.resolve("shared.csv");
        Path jdk = NewestJdk.atLeast(21);
        List<String> command = new ArrayList<>(List.of((jdk == null ? Path.of(System.getProperty("java.home")) : jdk)
                .resolve("bin").resolve("java").toString(), "-cp", System.getProperty("java.class.path"),
                HeadlessRunner.class.getName()));
        command.addAll(List.of(RUN));
        command.addAll(List.of("--pose-log", shared.toString(), "--robots-in-one-process", "--robot-jvm-opts",
                "-Drobosim.controlThreads=virtual"));
        Process p = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(dir.resolve("shared-run.txt").toFile()).start();
        assertTrue(p.waitFor(180, TimeUnit.SECONDS), "the shared run did not end");
        String output = Files.readString(dir.resolve("shared-run.txt"));
        assertEquals(0, p.exitValue(), output);
        assertTrue(output.contains("robots_in=one-process"), output);
        String kind = jdk == null ? "platform" : "virtual";
        assertTrue(output.contains("control code on " + kind + " threads"), output);
        if (jdk == null) {
            System.out.println("SameSeedSameRunTest: no JDK 21+ here: the shared connection compared on platform threads");
        }

        byte[] first = Files.readAllBytes(perRobot);
        byte[] second = Files.readAllBytes(shared);
        assertEquals(1 + 300 * 6, new String(first).lines().count());
        assertTrue(java.util.Arrays.equals(first, second), "the two pose logs differ");
    }

    /** The newest JDK of this machine (this JVM's, or one under the usual install directories), as the scripts look. */
    static final class NewestJdk {
        private NewestJdk() {
        }

        /** Its home if its feature version is at least {@code feature}, else null. */
        static Path atLeast(int feature) throws IOException {
            Path best = Runtime.version().feature() >= feature ? Path.of(System.getProperty("java.home")) : null;
            int bestVersion = best == null ? 0 : Runtime.version().feature();
            for (Path dir : List.of(Path.of("/usr/lib/jvm"), Path.of("/Library/Java/JavaVirtualMachines"))) {
                if (!Files.isDirectory(dir)) {
                    continue;
                }
                try (var homes = Files.list(dir)) {
                    for (Path h : homes.map(NewestJdk::home).toList()) {
                        int v = version(h);
                        if (v >= feature && v > bestVersion && Files.isExecutable(h.resolve("bin/java"))) {
                            best = h;
                            bestVersion = v;
                        }
                    }
                }
            }
            return best;
        }

        private static Path home(Path p) {
            return Files.isDirectory(p.resolve("Contents/Home")) ? p.resolve("Contents/Home") : p;
        }

        /** The feature version its {@code release} file names, or 0. */
        private static int version(Path home) {
            try {
                for (String line : Files.readAllLines(home.resolve("release"))) {
                    if (line.startsWith("JAVA_VERSION=\"")) {
                        String v = line.substring("JAVA_VERSION=\"".length()).split("[.\"]")[0];
                        return Integer.parseInt(v);
                    }
                }
            } catch (IOException | NumberFormatException e) {
                return 0;
            }
            return 0;
        }
    }
}
