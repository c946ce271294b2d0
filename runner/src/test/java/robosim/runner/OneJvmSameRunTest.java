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
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.environment.config.EnvironmentLoader;
import robosim.protocol.RecordingReader;

/**
 * A one-JVM run ({@code headless.sh --one-jvm}: the Environment, collision and sonar and every robot in one
 * JVM) is the same run as one with every part its own process: in a maze of noisy sonar (seed 42), a game of
 * tag (messages every step) and a world of laser, heat and bump sensors (messages too), 200 steps give the same
 * pose log, byte for byte, and recordings whose poses and messages ({@code record-tool.sh poses}, {@code
 * messages}) are the same. {@code scripts/check-one-jvm.sh} checks every world of test-envs/ so.
 */
class OneJvmSameRunTest {
    private static final int STEPS = 200;

    @TempDir
    Path dir;

    /** What one layout's run wrote. */
    private record Written(byte[] poseLog, String poses, String messages) {
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"maze.xml, false", "tag.xml, true", "sensors.xml, true"})
    void oneJvmGivesTheSamePoseLogAndRecordingAsEveryPartItsOwnProcess(String world, boolean talks)
            throws Exception {
        Written separate = run(world, "separate", "robots_in=processes");
        Written oneJvm = run(world, "one-jvm", "robots_in=one-jvm", "--one-jvm");
        int robots = new EnvironmentLoader().load(InJvmSimulation.env(world)).robots().size();
        assertEquals(1 + STEPS * robots, lines(separate.poseLog()).size(), "every robot's pose after every step");
        assertEquals(talks, separate.messages().lines().count() > 1, "messages delivered in " + world);
        assertSameLines("the pose log", lines(separate.poseLog()), lines(oneJvm.poseLog()));
        assertTrue(Arrays.equals(separate.poseLog(), oneJvm.poseLog()), "the pose logs differ in their bytes");
        assertSameLines("the recording's poses", separate.poses().lines().toList(), oneJvm.poses().lines().toList());
        assertSameLines("the recording's messages", separate.messages().lines().toList(),
                oneJvm.messages().lines().toList());
    }

    /** One headless run of {@code world} for {@link #STEPS} steps with a pose log and a recording. */
    private Written run(String world, String layout, String robotsIn, String... more) throws IOException {
        Path poseLog = dir.resolve(layout + ".csv");
        Path record = dir.resolve(layout + ".rec");
        List<String> args = new ArrayList<>(List.of("--env", InJvmSimulation.env(world).toString(),
                "--steps", Integer.toString(STEPS), "--pose-log", poseLog.toString(), "--record", record.toString(),
                "--timeout-s", "100"));
        args.addAll(List.of(more));
        HeadlessRun r = HeadlessRun.of(args.toArray(String[]::new));
        assertEquals(0, r.code(), r.all());
        assertTrue(r.summary().startsWith("steps=" + STEPS + " ") && r.summary().endsWith(" " + robotsIn), r.all());
        try (RecordingReader reader = new RecordingReader(record)) {
            StringWriter poses = new StringWriter();
            try (BufferedWriter out = new BufferedWriter(poses)) {
                RecordToolMain.poses(reader, out);
            }
            StringWriter messages = new StringWriter();
            try (BufferedWriter out = new BufferedWriter(messages)) {
                RecordToolMain.messages(reader, out);
            }
            return new Written(Files.readAllBytes(poseLog), poses.toString(), messages.toString());
        }
    }

    private static List<String> lines(byte[] text) {
        return new String(text, StandardCharsets.UTF_8).lines().toList();
    }

    /** Fails naming the first line where the two runs' {@code what} differ, and that line of each. */
    private static void assertSameLines(String what, List<String> separate, List<String> oneJvm) {
        int n = Math.min(separate.size(), oneJvm.size());
        int i = 0;
        while (i < n && separate.get(i).equals(oneJvm.get(i))) {
            i++;
        }
        if (i < n || separate.size() != oneJvm.size()) {
            fail(what + " differs at line " + (i + 1) + ": separate processes '"
                    + (i < separate.size() ? separate.get(i) : "(no line)") + "', one JVM '"
                    + (i < oneJvm.size() ? oneJvm.get(i) : "(no line)") + "'");
        }
    }
}
