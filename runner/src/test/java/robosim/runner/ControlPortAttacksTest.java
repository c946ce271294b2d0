package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.RandomAccessFile;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.environment.control.ControlServer;
import robosim.control.ControlClient;
import robosim.protocol.SimulationKeys;
import robosim.environment.config.EnvironmentLoader;

/**
 * A hostile client on the control port: pipelined requests are answered in order; {@code load} reads
 * only regular files of bounded size inside the environment directories, and each refusal is a reply
 * while the port goes on answering; connections over the cap are closed at once.
 */
class ControlPortAttacksTest {
    /** A proof deadline short enough to wait for (a client that proves in time: ControlPortTest). */
    private static final int SHORT_PROOF_DEADLINE_MS = 4000;
    private static final ObjectMapper JSON = new ObjectMapper();

    /** three-robots.xml copied into {@code dir}, which becomes one of the environment directories. */
    private static Path three(Path dir) throws IOException {
        return Files.copy(Path.of("src/test/resources/three-robots.xml"), dir.resolve("three.xml"));
    }

    @Test
    void pipelinedRequestsAreAnsweredInTheirOrder(@TempDir Path dir) throws Exception {
        Path file = three(dir);
        try (ControlFixture f = new ControlFixture(file, null);
                Socket raw = new Socket(InetAddress.getLoopbackAddress(), f.control.port())) {
            raw.setSoTimeout(ControlFixture.TIMEOUT_MS);
            // a load (which waits for the old run to close) then two requests that answer at once
            raw.getOutputStream().write(("load " + file + "\nstatus\nnonsense\n").getBytes(StandardCharsets.UTF_8));
            raw.getOutputStream().flush();
            BufferedReader in = new BufferedReader(new InputStreamReader(raw.getInputStream(), StandardCharsets.UTF_8));
            JsonNode first = JSON.readTree(in.readLine());
            JsonNode second = JSON.readTree(in.readLine());
            JsonNode third = JSON.readTree(in.readLine());
            assertTrue(first.path("message").asText().startsWith("loaded "), "the load's reply first: " + first);
            assertEquals("WAITING", second.path("state").asText(), "then the status: " + second);
            assertTrue(third.path("error").asText().startsWith("unknown request"), "then the error: " + third);
        }
    }

    @Test
    void loadReadsOnlyBoundedRegularFilesInsideTheEnvironmentDirectories(@TempDir Path dir) throws Exception {
        Path file = three(dir);
        Path fifo = dir.resolve("fifo.xml");
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assertTrue(mkfifo.waitFor(60, TimeUnit.SECONDS) && mkfifo.exitValue() == 0, "mkfifo");
        Path oversize = dir.resolve("huge.xml");
        try (RandomAccessFile r = new RandomAccessFile(oversize.toFile(), "rw")) {
            r.setLength(EnvironmentLoader.MAX_FILE_BYTES + 1L); // sparse: no disk used
        }
        Path toZero = Files.createSymbolicLink(dir.resolve("zero.xml"), Path.of("/dev/zero"));
        try (ControlFixture f = new ControlFixture(file, null); ControlClient c = f.client(null)) {
            String[][] refusals = {
                {"load " + fifo, fifo + ": not a regular file"},
                {"load " + oversize, oversize + ": larger than the " + EnvironmentLoader.MAX_FILE_BYTES + " bytes"},
                {"load " + toZero, toZero + ": links outside the environment directories"},
                {"load /dev/zero", "/dev/zero: outside the environment directories"},
                {"load /proc/self/fd/0", "/proc/self/fd/0: outside the environment directories"},
                {"load " + dir.resolve("../../etc/passwd"), ": outside the environment directories"},
                {"load " + dir.resolve("missing.xml"), "missing.xml: file not found"},
            };
            for (String[] r : refusals) {
                JsonNode reply = c.request(r[0]);
                assertFalse(reply.path("ok").asBoolean(), r[0] + " -> " + reply);
                assertTrue(reply.path("error").asText().contains(r[1]), r[0] + " -> " + reply);
                // the port, and its one thread for waiting requests, still answer
                assertTrue(c.request("status").path("ok").asBoolean());
            }
            Path faults = Files.writeString(dir.resolve("faults.xml"), Files.readString(file)
                    .replace("timeStepMs=\"", "timeStepMs=\"-").replace("type=\"ArRobot\"", "type=\"Roomba\""));
            String error = c.request("load " + faults).path("error").asText();
            assertTrue(error.matches(".*faults\\.xml:\\d+:\\d+: <environment> timeStepMs must be > 0, got -\\d+; "
                    + ".*faults\\.xml:\\d+:\\d+: <robot name=.*"), "a file's faults on one line: " + error);
            assertTrue(c.request("load " + file).path("ok").asBoolean(), "a file inside still loads");
            assertEquals("WAITING", c.request("status").path("state").asText());
        }
    }

    @Test
    void connectionsOverTheCapAreClosedAtOnce(@TempDir Path dir) throws Exception {
        try (ControlFixture f = new ControlFixture(three(dir), null)) {
            List<Socket> held = new ArrayList<>();
            try {
                for (int i = 0; i < ControlServer.MAX_CONNECTIONS; i++) {
                    held.add(new Socket(InetAddress.getLoopbackAddress(), f.control.port()));
                }
                // each held connection is answered, so all of them have been taken in before the next one
                for (Socket s : held) {
                    s.setSoTimeout(ControlFixture.TIMEOUT_MS);
                    s.getOutputStream().write("status\n".getBytes(StandardCharsets.UTF_8));
                    assertTrue(new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8))
                            .readLine().contains("\"ok\":true"));
                }
                try (Socket oneTooMany = new Socket(InetAddress.getLoopbackAddress(), f.control.port())) {
                    oneTooMany.setSoTimeout(ControlFixture.TIMEOUT_MS);
                    assertEquals(-1, oneTooMany.getInputStream().read(), "closed at once, before any request");
                }
            } finally {
                for (Socket s : held) {
                    s.close();
                }
            }
            // once they are gone, clients are served again (the count drops as each closes: wait for it)
            long giveUp = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ControlFixture.TIMEOUT_MS);
            boolean served = false;
            while (!served && System.nanoTime() < giveUp) {
                try (ControlClient c = f.client(null)) {
                    served = c.request("status").path("ok").asBoolean();
                } catch (IOException closedAtOnce) {
                    Thread.sleep(50); // the held connections' closes are still being counted
                }
            }
            assertTrue(served, "served again once the held connections closed");
        }
    }

    @Test
    void withKeysAConnectionThatDoesNotProveTheSecretIsClosed(@TempDir Path dir) throws Exception {
        SimulationKeys keys = TestKeys.keys(dir, "keys");
        try (ControlFixture f = new ControlFixture(three(dir), keys, 0, SHORT_PROOF_DEADLINE_MS);
                Socket raw = new Socket(InetAddress.getLoopbackAddress(), f.control.port());
                Socket silent = keys.tls().client(raw)) {
            raw.setSoTimeout(ControlFixture.TIMEOUT_MS);
            assertEquals(-1, silent.getInputStream().read(), "closed " + SHORT_PROOF_DEADLINE_MS
                    + " ms after connecting (over TLS) without proving the secret");
        }
    }
}
