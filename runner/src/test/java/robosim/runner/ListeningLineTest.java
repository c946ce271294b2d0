package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The Environment's listening line says whether its ports speak TLS: keys you can see (issue 31, item 7). */
class ListeningLineTest {
    private static final long LONG_S = 60;

    private static Map<String, String> listening(Path keys) throws Exception {
        List<String> command = ProcessLines.java(List.of(), "robosim.environment.EnvironmentMain",
                "src/test/resources/three-robots.xml", "--no-geometry", "--robot-port", "0", "--viewer-port", "0",
                "--control-port", "-1");
        ProcessBuilder pb = new ProcessBuilder(command);
        pb.environment().remove("ROBOSIM_KEYS");
        if (keys != null) {
            pb.environment().put("ROBOSIM_KEYS", keys.toString());
        }
        try (ProcessLines env = new ProcessLines("environment", pb)) {
            return HeadlessRunner.fields(env.await("listening robots=", LONG_S));
        }
    }

    @Test
    void theListeningLineSaysWhetherThePortsSpeakTls(@TempDir Path dir) throws Exception {
        assertEquals("off", listening(null).get("tls"));
        assertEquals("on", listening(TestKeys.make(dir, "sim")).get("tls"));
    }
}
