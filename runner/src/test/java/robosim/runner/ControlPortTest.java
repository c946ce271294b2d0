package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.control.ControlClient;
import robosim.protocol.SimulationKeys;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.control.ControlServer;

/** The control port over real sockets: start, stop, pause, resume, step N, status, load, bad input, keys. */
class ControlPortTest {
    private static final Path THREE = Path.of("src/test/resources/three-robots.xml");
    private static final int TIMEOUT_MS = 60_000;

    static JsonNode ok(ControlClient c, String request) throws IOException {
        JsonNode r = c.request(request);
        assertTrue(r.path("ok").asBoolean(), request + " -> " + r);
        return r;
    }

    @Test
    void addLetsANewRobotJoinAtItsPoseAndRefusesWhatCannotBe() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            List<CompletableFuture<String>> robots = f.robots();
            assertEquals("paused at step 5", ok(c, "step 5").path("message").asText());
            ok(c, "pause");
            assertTrue(ok(c, "add r9 Scout 11 2 180").path("message").asText().startsWith("added r9: it joins when"));
            for (String[] bad : new String[][] {{"add r9 Scout 11 3 0", "add r9: a robot named r9 is added already"},
                    {"add r1 Scout 11 3 0", "add r1: a robot named r1 is in the simulation"},
                    {"add r7 Scout 20 2 0", "add r7: (20.0, 2.0) m is not inside the arena for a Scout"},
                    {"add r6 Hover 5 2 0", "add r6: type \"Hover\" is not a known robot type"},
                    {"add r5 Scout one 2 0", "add: X must be a number, got \"one\""},
                    {"add r4 Scout 5", "add needs NAME TYPE X Y HEADING [CONTROL]"}}) {
                JsonNode r = c.request(bad[0]);
                assertTrue(!r.path("ok").asBoolean() && r.path("error").asText().startsWith(bad[1]), bad[0] + " -> " + r);
            }
            try (RawRobot r9 = new RawRobot("r9", robosim.devices.RobotTypes.properties("Scout"), f.host.ports()[0])) {
                assertTrue(r9.welcome.isAccepted(), r9.welcome.reason());
                assertEquals(11_000, r9.welcome.xMm());
                assertEquals(2_000, r9.welcome.yMm());
                assertEquals(180, r9.welcome.headingDeg());
                assertEquals(List.of("r1", "r2", "r3", "r9"), r9.welcome.robotNames());
                JsonNode taken = c.request("add r8 Scout 11 2 0");
                assertEquals("add r8: (11.0, 2.0) m is taken: robot r9 stands there", taken.path("error").asText());
                CompletableFuture<Long> drives = CompletableFuture.supplyAsync(() -> {
                    try {
                        while (r9.next() && r9.step(50, 0, false, List.of()) != null) {
                            // (until the end)
                        }
                        return r9.firstStep;
                    } catch (IOException e) {
                        throw new IllegalStateException(e);
                    }
                }, TestThreads.ROBOTS);
                assertEquals("paused at step 7", ok(c, "step 2").path("message").asText());
                JsonNode list = ok(c, "robots").path("robots");
                assertEquals("r9 running", list.get(3).path("name").asText() + " " + list.get(3).path("state").asText());
                ok(c, "stop");
                assertEquals(6, drives.get(TIMEOUT_MS, TimeUnit.MILLISECONDS), "it took part from the step after the one held");
            }
            for (CompletableFuture<String> r : robots) {
                r.get(TIMEOUT_MS, TimeUnit.MILLISECONDS);
            }
        }
    }

    @Test
    void removeTakesARobotOutOfTheRunForGoodAndRobotsListsEachState() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            assertEquals("expected", ok(c, "robots").path("robots").get(0).path("state").asText());
            List<CompletableFuture<String>> robots = f.robots();
            assertEquals("paused at step 10", ok(c, "step 10").path("message").asText());
            ok(c, "pause"); // returns once the 11th step is computed and held
            assertEquals("removed r2", ok(c, "remove r2").path("message").asText());
            assertEquals("removed from the simulation from the control port",
                    robots.get(1).get(TIMEOUT_MS, TimeUnit.MILLISECONDS), "the robot is told");
            assertEquals("paused at step 11", ok(c, "step 1").path("message").asText());
            JsonNode list = ok(c, "robots").path("robots");
            assertEquals("r1 running", list.get(0).path("name").asText() + " " + list.get(0).path("state").asText());
            assertEquals("r2 gone 12", list.get(1).path("name").asText() + " " + list.get(1).path("state").asText()
                    + " " + list.get(1).path("since").asLong(), "it went at the end of step 11, the one held when it was "
                    + "removed: the 12th is the first it took no part in");
            assertEquals(list, ok(c, "status").path("robot_states"));
            for (String[] bad : new String[][] {{"remove r2", "robot \"r2\" has already left"},
                    {"remove nobody\u0007", "no robot named \"nobody?\" in"}, {"remove", "remove needs a robot's name"}}) {
                JsonNode r = c.request(bad[0]);
                assertTrue(!r.path("ok").asBoolean() && r.path("error").asText().startsWith(bad[1]), bad[0] + " -> " + r);
            }
            assertEquals("paused at step 21", ok(c, "step 10").path("message").asText(), "the others go on");
            ok(c, "stop");
        }
    }

    @Test
    void stepPauseResumeStopAndStartChangeTheStepCounterAsTheyShould() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            assertEquals("WAITING", ok(c, "status").path("state").asText());
            List<CompletableFuture<String>> robots = f.robots();
            // started paused: step N runs exactly N steps and holds again
            assertEquals("paused at step 10", ok(c, "step 10").path("message").asText());
            JsonNode s = ok(c, "status");
            assertEquals("PAUSED", s.path("state").asText());
            assertEquals(10, s.path("step").asLong());
            assertEquals(3, s.path("connected").size());
            assertEquals("paused at step 15", ok(c, "step 5").path("message").asText());
            assertEquals(15, ok(c, "status").path("step").asLong(), "a paused Environment stays put");
            ok(c, "resume");
            String paused = ok(c, "pause").path("message").asText();
            long at = Long.parseLong(paused.substring("paused at step ".length()));
            assertTrue(at >= 15, paused);
            assertEquals(at, ok(c, "status").path("step").asLong());
            assertEquals("paused at step " + (at + 1), ok(c, "step 1").path("message").asText());
            // stop ends the simulation and tells the robots
            ok(c, "stop");
            assertEquals("ENDED", ok(c, "status").path("state").asText());
            for (CompletableFuture<String> r : robots) {
                assertEquals("stopped from the control port", r.get(TIMEOUT_MS, TimeUnit.MILLISECONDS));
            }
            // start runs the file again: a new simulation waits for its robots
            assertTrue(ok(c, "start").path("message").asText().startsWith("started a new simulation"));
            assertEquals("WAITING", ok(c, "status").path("state").asText());
            assertEquals(0, ok(c, "status").path("step").asLong());
            List<CompletableFuture<String>> again = f.robots();
            ok(c, "pause");
            long s0 = ok(c, "status").path("step").asLong();
            assertEquals("paused at step " + (s0 + 3), ok(c, "step 3").path("message").asText());
            ok(c, "stop");
            for (CompletableFuture<String> r : again) {
                r.get(TIMEOUT_MS, TimeUnit.MILLISECONDS);
            }
        }
    }

    @Test
    void loadingANewFileEndsTheRunningOneAndWaitsForTheNewRobots() throws Exception {
        Path other = InJvmSimulation.env("test.xml").toRealPath();
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            List<CompletableFuture<String>> robots = f.robots();
            ok(c, "step 5");
            JsonNode loaded = ok(c, "load " + other);
            assertTrue(loaded.path("message").asText().startsWith("loaded " + other), loaded.toString());
            for (CompletableFuture<String> r : robots) {
                assertEquals("a new environment file was loaded: " + other, r.get(TIMEOUT_MS, TimeUnit.MILLISECONDS));
            }
            JsonNode s = ok(c, "status");
            assertEquals("WAITING", s.path("state").asText());
            assertEquals(other.toString(), s.path("file").asText());
            List<String> names = new ArrayList<>();
            s.path("robots").forEach(n -> names.add(n.asText()));
            assertEquals(new EnvironmentLoader().load(other).robots().stream().map(r -> r.name()).toList(), names);
            List<CompletableFuture<String>> newRobots = f.robots();
            ok(c, "pause");
            ok(c, "step 4");
            assertTrue(ok(c, "status").path("step").asLong() >= 4);
            assertEquals(names.size(), ok(c, "status").path("connected").size());
            ok(c, "stop");
            for (CompletableFuture<String> r : newRobots) {
                r.get(TIMEOUT_MS, TimeUnit.MILLISECONDS);
            }
        }
    }

    @Test
    void badRequestsGetAnErrorReplyAndTheSimulationRunsOn() throws Exception {
        try (ControlFixture f = new ControlFixture(THREE, null); ControlClient c = f.client(null)) {
            f.robots();
            ok(c, "step 2");
            assertError(c, "jump over the moon", "unknown request");
            assertError(c, "step", "positive whole number");
            assertError(c, "step -4", "positive whole number");
            assertError(c, "step 1e99", "positive whole number");
            assertError(c, "load /no/such/file.xml", "/no/such/file.xml: outside the environment directories");
            assertError(c, "load", "load needs a file");
            // bytes that are not text, and a line far over the limit: an error, then the connection closes
            try (Socket raw = new Socket(InetAddress.getLoopbackAddress(), f.control.port())) {
                raw.setSoTimeout(TIMEOUT_MS);
                OutputStream out = raw.getOutputStream();
                out.write(new byte[] {(byte) 0xff, (byte) 0xfe, 'x', 'y', (byte) 0xfd, '\n'});
                out.flush();
                java.io.BufferedReader in = new java.io.BufferedReader(new java.io.InputStreamReader(raw.getInputStream(),
                        StandardCharsets.UTF_8));
                String first = in.readLine();
                assertTrue(first.contains("unknown request"), first);
                byte[] flood = new byte[ControlServer.MAX_LINE * 3];
                java.util.Arrays.fill(flood, (byte) 'x');
                out.write(flood);
                out.flush();
                StringBuilder rest = new StringBuilder();
                try {
                    for (String l = in.readLine(); l != null; l = in.readLine()) {
                        rest.append(l).append('\n');
                    }
                } catch (java.net.SocketException reset) {
                    // closed with our flood unread: also closed
                }
                String replies = rest.toString();
                assertTrue(replies.contains("request longer than " + ControlServer.MAX_LINE + " bytes"), replies);
            }
            // the simulation and the control port are fine
            assertEquals("paused at step 5", ok(c, "step 3").path("message").asText());
            try (ControlClient again = f.client(null)) {
                assertEquals(5, ok(again, "status").path("step").asLong());
            }
        }
    }

    @Test
    void withKeysEveryRequestWaitsForTheProofOverTls(@TempDir Path dir) throws Exception {
        SimulationKeys keys = TestKeys.keys(dir, "keys");
        try (ControlFixture f = new ControlFixture(THREE, keys)) {
            // no keys at all: TLS never lets it in, and it is told so at once
            try (ControlClient c = f.client(null)) {
                JsonNode told = c.request("status");
                assertFalse(told.path("ok").asBoolean(), told.toString());
                assertEquals("the Environment speaks TLS (tls=on): set ROBOSIM_KEYS to the simulation's keys",
                        told.path("error").asText());
            }
            // another simulation's keys: refused at TLS (its key pair is not this one)
            IOException other = assertThrows(IOException.class, () -> f.client(TestKeys.keys(dir, "other")).close());
            assertTrue(other.getMessage().contains("TLS handshake with 127.0.0.1:" + f.control.port() + " failed"),
                    other.getMessage());
            // this simulation's key pair but no proof yet: nothing but challenge and prove is served
            try (Socket raw = new Socket(InetAddress.getLoopbackAddress(), f.control.port());
                    Socket tls = keys.tls().client(raw)) {
                raw.setSoTimeout(ControlFixture.TIMEOUT_MS);
                java.io.BufferedReader in = new java.io.BufferedReader(
                        new java.io.InputStreamReader(tls.getInputStream(), StandardCharsets.UTF_8));
                OutputStream out = tls.getOutputStream();
                out.write("status\nprove 00\nchallenge\nprove ".getBytes(StandardCharsets.UTF_8));
                out.write(("00".repeat(32) + "\nstop\n").getBytes(StandardCharsets.UTF_8));
                out.flush();
                assertTrue(in.readLine().contains("prove the shared secret first"));
                assertTrue(in.readLine().contains("not the proof for the last challenge"));
                assertTrue(in.readLine().contains("\"nonce\""));
                assertTrue(in.readLine().contains("not the proof for the last challenge"), "a wrong proof");
                assertTrue(in.readLine().contains("prove the shared secret first"), "still not proven: no stop");
            }
            try (ControlClient c = f.client(keys)) {
                assertEquals("WAITING", ok(c, "status").path("state").asText());
                JsonNode challenge = c.request("challenge");
                assertEquals(64, challenge.path("nonce").asText().length(), challenge.toString());
                assertError(c, "prove " + "00".repeat(32), "not the proof");
            }
        }
    }

    private static void assertError(ControlClient c, String request, String part) throws IOException {
        JsonNode r = c.request(request);
        assertFalse(r.path("ok").asBoolean(), request + " -> " + r);
        assertTrue(r.path("error").asText().contains(part), request + " -> " + r);
    }

    private static String readToEnd(InputStream in) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        byte[] buf = new byte[4096];
        try {
            for (int n = in.read(buf); n >= 0; n = in.read(buf)) {
                b.write(buf, 0, n);
            }
        } catch (java.net.SocketException reset) {
            // closed with data unread: also closed
        }
        return b.toString(StandardCharsets.UTF_8);
    }
}
