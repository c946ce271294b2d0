package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.environment.config.EnvironmentLoader;
import robosim.protocol.RecordingReader;

/**
 * One run, whatever the layout: the same pose log, byte for byte, and recordings whose poses and messages
 * ({@code record-tool.sh poses}, {@code messages}) are the same. {@code headless.sh} for real, every part its own OS
 * process (the Environment, the Geometry process and a robot process each), gives in a world of laser, heat and bump
 * sensors and messages what the whole simulation in one JVM ({@code --one-jvm}) gives; in a maze of noisy sonar
 * (seed 42), the robots of one process over one shared connection with control code on virtual threads give what
 * one JVM with control code on platform threads gives (both on the newest JDK 21+ this machine has, so only the
 * layout, the connection and the thread kind differ; on a machine without one, on this JVM's with platform threads
 * in both, and the test says so); and a game of tag (messages every step) gives in one JVM what its robots give over
 * a shared connection to the Environment and Geometry processes. {@code scripts/check-one-jvm.sh} checks every world
 * of test-envs/ so.
 */
class SameRunEveryLayoutTest {
    private static final int STEPS = 200;
    private static final String ROBOT_JVM = "-XX:+UseSerialGC -XX:TieredStopAtLevel=1 -Drobosim.controlThreads=";

    @TempDir
    Path dir;

    /** What one layout's run wrote, and what it printed. */
    private record Written(byte[] poseLog, String poses, String messages, String readings, String scene,
            String output) {
    }

    @Test
    void everyPartItsOwnProcessIsTheSameRunAsOneJvm() throws Exception {
        Written separate = inThisJvm("sensors.xml", "separate", "robots_in=processes", "--profile",
                dir.resolve("profile").toString());
        String last = separate.output().lines().filter(l -> l.startsWith("steps=")).reduce((a, b) -> b).orElse("");
        assertTrue(last.matches("steps=" + STEPS + " robots=3 wall_s=[0-9.]+ steps_per_s=[0-9.]+ "
                + "robot_steps_per_s=[0-9.]+ .*geometry=process robots_in=processes"), separate.output());
        assertTrue(Files.size(dir.resolve("profile/environment.jfr")) > 0, "--profile recorded the Environment");
        assertTrue(Files.size(dir.resolve("profile/geometry.jfr")) > 0, "--profile recorded Geometry");
        List<String> rows = lines(separate.poseLog());
        assertEquals("step,robot,x_m,y_m,heading_deg,state", rows.get(0));
        assertEquals(1 + STEPS * 3, rows.size(), "every robot's pose after every step");
        assertTrue(separate.messages().lines().count() > 1, "messages delivered");
        assertSame("one JVM's", separate, inThisJvm("sensors.xml", "one-jvm", "robots_in=one-jvm", "--one-jvm"));
    }

    @Test
    void theMazeIsTheSameRunOverASharedConnectionOnVirtualThreadsAsInOneJvmOnPlatformThreads() throws Exception {
        Path newest = NewestJdk.atLeast(21);
        Path jdk = newest == null ? Path.of(System.getProperty("java.home")) : newest;
        String kind = newest == null ? "platform" : "virtual";
        Written shared = spawned(jdk, List.of(), "maze.xml", "shared", "--robots-in-one-process", "--robot-jvm-opts",
                ROBOT_JVM + kind);
        assertTrue(shared.output().lines().anyMatch(l -> l.endsWith("robots_in=one-process")), shared.output());
        assertTrue(shared.output().contains("control code on " + kind + " threads"), shared.output());
        if (newest == null) {
            System.out.println("SameRunEveryLayoutTest: no JDK 21+ here: the shared connection compared on platform "
                    + "threads");
        }
        assertEquals(1 + STEPS * 6, lines(shared.poseLog()).size(), "every robot's pose after every step");
        Written oneJvm = spawned(jdk, List.of("-Drobosim.controlThreads=platform"), "maze.xml", "one-jvm", "--one-jvm");
        assertTrue(oneJvm.output().lines().anyMatch(l -> l.endsWith("robots_in=one-jvm")), oneJvm.output());
        assertSame("one JVM's", shared, oneJvm);
    }

    @Test
    void aGameOfTagIsTheSameRunInOneJvmAsOverASharedConnection() throws Exception {
        Written shared = inThisJvm("tag.xml", "shared", "robots_in=one-process", "--robots-in-one-process");
        Written oneJvm = inThisJvm("tag.xml", "one-jvm", "robots_in=one-jvm", "--one-jvm");
        int robots = new EnvironmentLoader().load(InJvmSimulation.env("tag.xml")).robots().size();
        assertEquals(1 + STEPS * robots, lines(shared.poseLog()).size(), "every robot's pose after every step");
        assertTrue(shared.messages().lines().count() > 1, "messages delivered");
        assertSame("one JVM's", shared, oneJvm);
    }

    @Test
    void worldsOfObjectsLightsLedsCamerasAndMessagesAreTheSameRunOverTheGeometryProcessAsInOneJvm() throws Exception {
        // foraging: proximity, light and ground sensors, cans pushed and carried (through the Geometry process's
        // objects); fireflies: LEDs and cameras; aggregation: range-and-bearing messages; ARGoS's foraging: loop
        // functions that paint the floor, tell robots and report metrics
        for (String world : List.of("foraging.xml", "synchronization.xml", "aggregation.xml", "argos/foraging.xml")) {
            String layout = world.replace('/', '-');
            Written shared = inThisJvm(world, layout + "-shared", "robots_in=one-process", "--robots-in-one-process");
            assertTrue(shared.output().contains("geometry=process"), shared.output());
            Written oneJvm = inThisJvm(world, layout + "-one-jvm", "robots_in=one-jvm", "--one-jvm");
            assertTrue(shared.readings().lines().count() > STEPS, world + ": readings recorded");
            assertSame(world + ", one JVM's", shared, oneJvm);
        }
    }

    /** The pose logs are the same bytes, and the recordings' poses, messages, readings and scenes the same lines. */
    private static void assertSame(String which, Written first, Written other) {
        assertSameLines(which + " pose log", lines(first.poseLog()), lines(other.poseLog()));
        assertTrue(Arrays.equals(first.poseLog(), other.poseLog()), which + " pose log differs in its bytes");
        assertSameLines(which + " recording's poses", first.poses().lines().toList(), other.poses().lines().toList());
        assertSameLines(which + " recording's messages", first.messages().lines().toList(),
                other.messages().lines().toList());
        assertSameLines(which + " recording's readings", first.readings().lines().toList(),
                other.readings().lines().toList());
        assertSameLines(which + " recording's objects and LEDs", first.scene().lines().toList(),
                other.scene().lines().toList());
    }

    /** The arguments of a run of {@code world} for {@link #STEPS} steps with a pose log and a recording. */
    private List<String> args(String world, String layout, String... more) throws IOException {
        Path env = world.startsWith("argos/") ? Path.of("..", "examples", world) : InJvmSimulation.env(world);
        List<String> args = new ArrayList<>(List.of("--env", env.toString(), "--steps",
                Integer.toString(STEPS), "--pose-log", dir.resolve(layout + ".csv").toString(), "--record",
                dir.resolve(layout + ".rec").toString(), "--output-dir", dir.resolve(layout).toString(), "--timeout-s",
                "120"));
        args.addAll(List.of(more));
        return args;
    }

    /** A headless run in this JVM (its children, if any, on this JVM's JDK). */
    private Written inThisJvm(String world, String layout, String robotsIn, String... more) throws IOException {
        HeadlessRun r = HeadlessRun.of(args(world, layout, more).toArray(String[]::new));
        assertEquals(0, r.code(), r.all());
        assertTrue(r.summary().startsWith("steps=" + STEPS + " ") && r.summary().endsWith(" " + robotsIn), r.all());
        return written(layout, r.all());
    }

    /** A headless run on the JDK at {@code jdk}, its children too, the runner's JVM with {@code options}. */
    private Written spawned(Path jdk, List<String> options, String world, String layout, String... more)
            throws Exception {
        List<String> command = new ArrayList<>(List.of(jdk.resolve("bin").resolve("java").toString()));
        command.addAll(options);
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), HeadlessRunner.class.getName()));
        command.addAll(args(world, layout, more));
        Path out = dir.resolve(layout + ".txt");
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(out.toFile()).start();
        try {
            assertTrue(p.waitFor(180, TimeUnit.SECONDS), "the run did not end: " + Files.readString(out));
        } finally {
            p.descendants().forEach(ProcessHandle::destroyForcibly); // (its children, if it did not end)
            p.destroyForcibly();
        }
        String output = Files.readString(out);
        assertEquals(0, p.exitValue(), output);
        return written(layout, output);
    }

    private Written written(String layout, String output) throws IOException {
        try (RecordingReader reader = new RecordingReader(dir.resolve(layout + ".rec"))) {
            StringWriter poses = new StringWriter();
            try (BufferedWriter out = new BufferedWriter(poses)) {
                RecordToolMain.poses(reader, out);
            }
            StringWriter messages = new StringWriter();
            try (BufferedWriter out = new BufferedWriter(messages)) {
                RecordToolMain.messages(reader, out);
            }
            StringWriter readings = new StringWriter();
            try (BufferedWriter out = new BufferedWriter(readings)) {
                RecordToolMain.readings(reader, out);
            }
            StringBuilder scene = new StringBuilder(); // (each step's object poses and robots' LED colours)
            for (int k = 0; k < reader.steps(); k++) {
                robosim.protocol.PoseUpdate u = reader.step(k).update();
                scene.append(u.step());
                for (int o = 0; o < u.objectCount(); o++) {
                    scene.append(' ').append(u.objectXMm(o)).append(',').append(u.objectYMm(o)).append(',')
                            .append(u.objectHeadingDeg(o));
                }
                for (int r = 0; r < u.count(); r++) {
                    scene.append(' ').append(Arrays.toString(u.leds(r)));
                }
                scene.append(' ').append(u.paint()).append(' ').append(u.reports()); // (the loop functions')
                scene.append('\n');
            }
            return new Written(Files.readAllBytes(dir.resolve(layout + ".csv")), poses.toString(), messages.toString(),
                    readings.toString(), scene.toString(), output);
        }
    }

    private static List<String> lines(byte[] text) {
        return new String(text, StandardCharsets.UTF_8).lines().toList();
    }

    /** Fails naming the first line where the two runs' {@code what} differ, and that line of each. */
    private static void assertSameLines(String what, List<String> first, List<String> other) {
        int n = Math.min(first.size(), other.size());
        int i = 0;
        while (i < n && first.get(i).equals(other.get(i))) {
            i++;
        }
        if (i < n || first.size() != other.size()) {
            fail(what + " differs at line " + (i + 1) + ": '" + (i < first.size() ? first.get(i) : "(no line)")
                    + "' against '" + (i < other.size() ? other.get(i) : "(no line)") + "'");
        }
    }

    /** The newest JDK of this machine (this JVM's, or one under the usual install directories), as the scripts look. */
    static final class NewestJdk {
        private NewestJdk() {
        }

        /** Its home if its feature version is at least {@code feature}, else null. */
        static Path atLeast(int feature) throws IOException {
            Path best = Runtime.version().feature() >= feature ? Path.of(System.getProperty("java.home")) : null;
            int bestVersion = best == null ? 0 : Runtime.version().feature();
            for (Path home : List.of(Path.of("/usr/lib/jvm"), Path.of("/Library/Java/JavaVirtualMachines"))) {
                if (!Files.isDirectory(home)) {
                    continue;
                }
                try (var homes = Files.list(home)) {
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
