package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * {@code scripts/headless.sh} told to stop by SIGTERM mid-run: every process it started ends, and
 * every port the Environment listened on is free again.
 */
class HeadlessSignalsIT {
    private static final long LONG_S = 120;

    @Test
    void sigtermToHeadlessEndsEveryChildAndFreesThePorts() throws Exception {
        // real time (two 500 ms steps a second): the run is still going when the signal comes
        Process headless = new ProcessBuilder("bash", "../scripts/headless.sh", "--env",
                "src/test/resources/three-robots.xml", "--steps", "100000", "--speed", "1")
                .redirectErrorStream(true).start();
        BlockingQueue<String> lines = new LinkedBlockingQueue<>();
        List<String> seen = new ArrayList<>();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(
                    new InputStreamReader(headless.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line = r.readLine(); line != null; line = r.readLine()) {
                    lines.add(line);
                }
            } catch (IOException ignored) {
                // the process is gone
            }
        }, "test-headless-output");
        reader.setDaemon(true);
        reader.start();
        try {
            Map<String, String> ports = null;
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(LONG_S);
            while (true) {
                String line = lines.poll(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
                if (line == null) {
                    fail("no 'running' line within " + LONG_S + " s; output:\n" + String.join("\n", seen));
                }
                seen.add(line);
                if (line.startsWith("listening ")) {
                    ports = HeadlessRunner.fields(line);
                } else if (line.startsWith("running 3 robots")) {
                    break;
                }
            }
            assertTrue(ports != null, "the ports were printed before the start: " + seen);
            List<ProcessHandle> children = headless.descendants().toList();
            assertTrue(children.size() >= 5, "Environment, Geometry and three robots: " + children);

            headless.destroy(); // SIGTERM

            assertTrue(headless.waitFor(LONG_S, TimeUnit.SECONDS), "headless.sh ended");
            for (ProcessHandle child : children) {
                child.onExit().get(LONG_S, TimeUnit.SECONDS);
                assertTrue(!child.isAlive(), "child " + child.pid() + " ended");
            }
            for (String role : List.of("robots", "viewers", "geometry", "control")) {
                int port = Integer.parseInt(ports.get(role));
                try (ServerSocket s = new ServerSocket()) {
                    s.setReuseAddress(true); // as the Environment's own listening sockets
                    s.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
                }
            }
            assertEquals(143, headless.exitValue(), "ended by SIGTERM (128 + 15)");
        } finally {
            headless.descendants().forEach(ProcessHandle::destroyForcibly);
            headless.destroyForcibly();
        }
    }
}
