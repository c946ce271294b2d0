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

/**
 * Two runs of the maze (noisy sonar, seed 42) give identical pose logs, byte for byte, whatever the robots'
 * connection and thread kind: once as separate processes (a socket each, control code on platform threads),
 * once in one process over one shared connection with control code on virtual threads; both on the newest
 * JDK 21+ this machine has, so only the connection and the thread kind differ (on a machine with no JDK
 * 21+, both on this JVM's platform threads: the connection modes alone are compared then, and the test
 * says so).
 */
class SameSeedSameRunTest {
    private static final String[] RUN = {"--env", "../test-envs/maze.xml", "--steps", "300", "--timeout-s", "120"};
    private static final String ROBOT_JVM = "-XX:+UseSerialGC -XX:TieredStopAtLevel=1 -Drobosim.controlThreads=";

    @TempDir
    Path dir;

    /** A headless run on the JDK at {@code jdk} (its children too); returns its output. */
    private String headless(Path jdk, Path poseLog, String... more) throws Exception {
        List<String> command = new ArrayList<>(List.of(jdk.resolve("bin").resolve("java").toString(), "-cp",
                System.getProperty("java.class.path"), HeadlessRunner.class.getName()));
        command.addAll(List.of(RUN));
        command.addAll(List.of("--pose-log", poseLog.toString()));
        command.addAll(List.of(more));
        Path out = dir.resolve(poseLog.getFileName() + ".txt");
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(out.toFile()).start();
        try {
            assertTrue(p.waitFor(180, TimeUnit.SECONDS), "the run did not end: " + Files.readString(out));
        } finally {
            p.descendants().forEach(ProcessHandle::destroyForcibly); // (its children, if it did not end)
            p.destroyForcibly();
        }
        String output = Files.readString(out);
        assertEquals(0, p.exitValue(), output);
        return output;
    }

    @Test
    void theSameSeedGivesTheSamePoseLogOverEitherConnectionAndThreadKind() throws Exception {
        Path newest = NewestJdk.atLeast(21);
        Path jdk = newest == null ? Path.of(System.getProperty("java.home")) : newest;
        String kind = newest == null ? "platform" : "virtual";
        Path perRobot = dir.resolve("per-robot.csv");
        String first = headless(jdk, perRobot, "--robot-jvm-opts", ROBOT_JVM + "platform");
        assertTrue(first.contains("robots_in=processes"), first);
        assertTrue(first.contains("control code on platform threads"), first);
        Path shared = dir.resolve("shared.csv");
        String second = headless(jdk, shared, "--robots-in-one-process", "--robot-jvm-opts", ROBOT_JVM + kind);
        assertTrue(second.lines().anyMatch(l -> l.endsWith("robots_in=one-process")), second);
        assertTrue(second.contains("control code on " + kind + " threads"), second);
        if (newest == null) {
            System.out.println("SameSeedSameRunTest: no JDK 21+ here: the shared connection compared on platform threads");
        }
        byte[] a = Files.readAllBytes(perRobot);
        byte[] b = Files.readAllBytes(shared);
        assertEquals(1 + 300 * 6, new String(a).lines().count());
        assertTrue(java.util.Arrays.equals(a, b), "the two pose logs differ");
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
