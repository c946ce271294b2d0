package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Two hosts, as Linux network namespaces joined by a veth pair (10.231.0.1 and 10.231.0.2, nothing
 * else): the Environment on host A bound to its network address with the simulation's keys; on host B,
 * over that network, a robot without the keys and the Control Panel without them get nowhere, and
 * Geometry, two robots, a recording viewer and the Control Panel holding the keys run the whole
 * simulation over TLS. (That the Environment will not bind beyond loopback without the keys is
 * {@code EnvironmentMainTest}'s.) Needs root (namespaces) and iproute2 ({@code .ci/run} installs it).
 */
class TwoHostsIT {
    private static final long LONG_S = 120;
    private static final String HOST_A = "10.231.0.1";

    @Test
    @Timeout(value = 10, unit = TimeUnit.MINUTES) // (about ten JVMs one after another, on a loaded machine)
    void anEnvironmentOnOneHostServesRobotsViewersAndGeometryOnAnotherOnlyWithTheKeys(@TempDir Path dir)
            throws Exception {
        String suffix = Long.toString(ProcessHandle.current().pid() % 1_000_000);
        String a = "robosim-a-" + suffix;
        String b = "robosim-b-" + suffix;
        List<ProcessLines> started = new ArrayList<>();
        try {
            String why = tryRun("ip", "netns", "add", a);
            Assumptions.assumeTrue(why == null, "no network namespaces here (they need root and CAP_SYS_ADMIN): " + why);
            Path keys = TestKeys.make(dir, "keys");
            sh("ip netns add " + b,
                    "ip link add rsa" + suffix + " type veth peer name rsb" + suffix,
                    "ip link set rsa" + suffix + " netns " + a, "ip link set rsb" + suffix + " netns " + b,
                    "ip -n " + a + " addr add " + HOST_A + "/24 dev rsa" + suffix,
                    "ip -n " + b + " addr add 10.231.0.2/24 dev rsb" + suffix,
                    "ip -n " + a + " link set rsa" + suffix + " up", "ip -n " + b + " link set rsb" + suffix + " up",
                    "ip -n " + a + " link set lo up", "ip -n " + b + " link set lo up");

            ProcessLines env = start(started, a, keys, "environment.sh", "--bind", HOST_A, "../test-envs/test.xml",
                    "--steps", "200");
            env.await("listening robots=8000 viewers=3000 geometry=10000 control=8100", LONG_S);

            // host B without the keys: the robot's plain stream never gets a byte of the protocol, the Control
            // Panel's plain request is not served; each is told at once to set ROBOSIM_KEYS
            ProcessLines stranger = start(started, b, null, "robot.sh", "robosim.examples.BackAndForth", "robot1",
                    HOST_A, "8000", "--type", "ArRobot");
            ProcessLines panel = start(started, b, null, "control-panel.sh", HOST_A, "8100", "status");
            assertEquals(1, panel.exit(LONG_S), panel.output());
            panel.await("error=the Environment speaks TLS (tls=on): set ROBOSIM_KEYS to the simulation's keys", LONG_S);

            // host B with the keys (the robots last, once the stranger is gone)
            ProcessLines status = start(started, b, keys, "control-panel.sh", HOST_A, "8100", "status");
            assertEquals(0, status.exit(LONG_S), status.output());
            status.await("state=WAITING", LONG_S);
            Path poses = dir.resolve("poses.csv");
            ProcessLines viewer = start(started, b, keys, "pose-log.sh", HOST_A, "3000", poses.toString());
            start(started, b, keys, "geometry.sh", HOST_A, "10000");
            viewer.await("pose-log: recording " + HOST_A + ":3000", LONG_S);
            assertNotEquals(0, stranger.exit(LONG_S), stranger.output());
            stranger.await("robot robot1: " + HOST_A + ":8000: the Environment speaks TLS (tls=on): set ROBOSIM_KEYS to "
                    + "the simulation's keys", LONG_S);
            env.await("it spoke without TLS; told it the Environment speaks TLS", LONG_S);
            start(started, b, keys, "robots.sh", HOST_A, "8000", "--robot", "robot1:ArRobot:robosim.examples.BackAndForth",
                    "--robot", "robot2:Scout:robosim.examples.BackAndForth");

            assertEquals(0, env.exit(LONG_S), env.output());
            String summary = env.await("summary steps=", LONG_S);
            assertTrue(summary.startsWith("summary steps=200 robots=2 ") && summary.contains(" robots_removed=0 ")
                    && summary.contains(" geometry_losses=0"), summary);
            assertEquals(0, viewer.exit(LONG_S), viewer.output());
            viewer.await("pose-log: 200 steps written to " + poses, LONG_S);
            List<String> rows = Files.readAllLines(poses, StandardCharsets.UTF_8);
            assertEquals(1 + 200 * 2, rows.size(), "a header and both robots' poses at every step");
            assertTrue(rows.get(rows.size() - 1).startsWith("200,"), rows.get(rows.size() - 1));
        } finally {
            started.forEach(ProcessLines::close);
            for (ProcessLines p : started) {
                p.process.waitFor(LONG_S, TimeUnit.SECONDS);
            }
            for (String ns : List.of(a, b)) { // (the veth pair goes with them)
                new ProcessBuilder("ip", "netns", "del", ns).redirectErrorStream(true)
                        .redirectOutput(ProcessBuilder.Redirect.DISCARD).start().waitFor(LONG_S, TimeUnit.SECONDS);
            }
        }
    }

    /** Starts {@code scripts/SCRIPT ARGS} in namespace {@code ns}, with the keys in {@code keys} (or none). */
    private static ProcessLines start(List<ProcessLines> started, String ns, Path keys, String script, String... args)
            throws IOException {
        List<String> cmd = new ArrayList<>(List.of("ip", "netns", "exec", ns, "bash", "../scripts/" + script));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().remove("ROBOSIM_SECRET_FILE");
        pb.environment().remove("ROBOSIM_SECRET");
        pb.environment().remove("DISPLAY");
        if (keys == null) {
            pb.environment().remove("ROBOSIM_KEYS");
        } else {
            pb.environment().put("ROBOSIM_KEYS", keys.toString());
        }
        ProcessLines p = new ProcessLines(ns.charAt(8) + ":" + script, pb);
        started.add(p);
        return p;
    }

    /** Runs each command (no shell); fails naming the command and its output if one fails. */
    private static void sh(String... commands) throws IOException, InterruptedException {
        for (String c : commands) {
            String why = tryRun(c.split(" "));
            if (why != null) {
                throw new IOException(c + " failed: " + why);
            }
        }
    }

    /** Runs a command; null if it succeeded, else its output (or that it could not start). */
    private static String tryRun(String... command) throws InterruptedException {
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            return p.waitFor(LONG_S, TimeUnit.SECONDS) && p.exitValue() == 0 ? null : out.strip();
        } catch (IOException e) {
            return e.getMessage();
        }
    }
}
