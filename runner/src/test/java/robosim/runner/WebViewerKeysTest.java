package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocket;
import javax.net.ssl.TrustManagerFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.protocol.SimulationKeys;
import robosim.web.WebViewerServer;

/**
 * The browser viewer with the simulation's keys is protected like every other port: TLS with the
 * simulation's key pair, which the browser must show (imported from {@code simulation.p12}); a client
 * without it, or without TLS, gets nothing, and a page that has it gets the page and the feed (which
 * proves the keys on the viewer port). A secret without the key pair, or no keys beyond loopback, is refused.
 */
class WebViewerKeysTest {
    private static final int LONG_MS = 60_000;

    @Test
    void withKeysOnlyABrowserHoldingTheKeyPairIsServed(@TempDir Path dir) throws Exception {
        Path keysDir = TestKeys.make(dir, "keys");
        SimulationKeys keys = SimulationKeys.fromDirectory(keysDir);
        char[] secret = Files.readString(keysDir.resolve("secret")).strip().toCharArray();
        CountDownLatch checked = new CountDownLatch(1);
        String[] got = new String[4];
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml")).keys(keys)
                .sideline((env, ports) -> {
                    try (WebViewerServer web = new WebViewerServer("127.0.0.1", ports[1], keys, (verb, arg) -> "{}")) {
                        web.start(InetAddress.getLoopbackAddress(), 0);
                        int port = web.port();
                        try (SSLSocket page = socket(context(keysDir, secret, true), port)) {
                            got[0] = request(page, "GET / HTTP/1.1\r\nHost: 10.1.2.3:" + port + "\r\nConnection: close\r\n\r\n");
                        }
                        try (SSLSocket page = socket(context(keysDir, secret, true), port)) {
                            got[1] = firstFrame(page, port);
                        }
                        try (SSLSocket stranger = socket(context(keysDir, secret, false), port)) {
                            got[2] = "served: " + request(stranger, "GET / HTTP/1.1\r\nHost: localhost\r\n\r\n");
                        } catch (IOException e) {
                            got[2] = "refused: " + e;
                        }
                        try (java.net.Socket plain = new java.net.Socket(InetAddress.getLoopbackAddress(), port)) {
                            plain.setSoTimeout(LONG_MS);
                            plain.getOutputStream().write("GET / HTTP/1.1\r\nHost: localhost\r\n\r\n"
                                    .getBytes(StandardCharsets.US_ASCII));
                            got[3] = "answered: " + line(plain.getInputStream());
                        } catch (IOException e) {
                            got[3] = "refused: " + e;
                        }
                    } finally {
                        checked.countDown();
                    }
                }).run(10, true, () -> robot -> {
                    checked.await(LONG_MS, TimeUnit.MILLISECONDS);
                    new Chatter().run(robot);
                });
        assertTrue(sim.summary.completed(), sim.summary.reason());
        assertTrue(got[0].startsWith("HTTP/1.1 200"), "the page, to a browser with the key pair, by any host name: " + got[0]);
        assertTrue(got[1].startsWith("{\"type\":\"snapshot\""), "and its feed over wss: " + got[1]);
        assertTrue(got[2].startsWith("refused: "), "a client without the key pair gets nothing: " + got[2]);
        assertTrue(got[3].startsWith("answered: HTTP/1.1 400"), "nor one without TLS, which is told to use https: "
                + got[3]);

        IllegalArgumentException secretOnly = assertThrows(IllegalArgumentException.class,
                () -> new WebViewerServer("127.0.0.1", 1, SimulationKeys.of("a secret of more than sixteen", "test"),
                        (v, a) -> "{}"));
        assertTrue(secretOnly.getMessage().contains("needs the simulation's key pair"), secretOnly.getMessage());
        WebViewerServer open = new WebViewerServer("127.0.0.1", 1, null, (v, a) -> "{}");
        IOException beyond = assertThrows(IOException.class, () -> open.start(InetAddress.getByName("0.0.0.0"), 0));
        assertTrue(beyond.getMessage().contains("beyond loopback only with the simulation's keys"), beyond.getMessage());
    }

    /** TLS as a browser that imported simulation.p12 does it ({@code withKey}), or one that only trusts it. */
    private static SSLContext context(Path keysDir, char[] secret, boolean withKey) throws Exception {
        KeyStore store = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(keysDir.resolve("simulation.p12"))) {
            store.load(in, secret);
        }
        KeyStore trusted = KeyStore.getInstance("PKCS12");
        trusted.load(null, null);
        trusted.setCertificateEntry("simulation", store.getCertificate(store.aliases().nextElement()));
        TrustManagerFactory tm = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
        tm.init(trusted);
        KeyManagerFactory km = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        km.init(store, secret);
        SSLContext c = SSLContext.getInstance("TLSv1.3");
        c.init(withKey ? km.getKeyManagers() : null, tm.getTrustManagers(), null);
        return c;
    }

    private static SSLSocket socket(SSLContext c, int port) throws IOException {
        SSLSocket s = (SSLSocket) c.getSocketFactory().createSocket(InetAddress.getLoopbackAddress(), port);
        s.setSoTimeout(LONG_MS);
        s.startHandshake();
        return s;
    }

    /** Sends {@code request}; the status line of the answer (TLS 1.3 reports a refused client key on the first read). */
    private static String request(SSLSocket s, String request) throws IOException {
        s.getOutputStream().write(request.getBytes(StandardCharsets.US_ASCII));
        s.getOutputStream().flush();
        return line(s.getInputStream());
    }

    /** Opens the feed's WebSocket as the page does and returns its first text message. */
    private static String firstFrame(SSLSocket s, int port) throws IOException {
        String status = request(s, "GET /ws HTTP/1.1\r\nHost: localhost:" + port + "\r\nUpgrade: websocket\r\n"
                + "Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n"
                + "Origin: https://localhost:" + port + "\r\n\r\n");
        assertTrue(status.startsWith("HTTP/1.1 101"), status);
        DataInputStream in = new DataInputStream(s.getInputStream());
        while (!line(in).isEmpty()) {
            // (the rest of the upgrade's headers)
        }
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        boolean fin;
        do {
            int head = in.readUnsignedByte();
            fin = (head & 0x80) != 0;
            long n = in.readUnsignedByte() & 0x7f; // (a server's frames are not masked)
            n = n == 126 ? in.readUnsignedShort() : n == 127 ? in.readLong() : n;
            assertTrue(n < 1 << 20, "a frame of " + n + " bytes");
            byte[] b = new byte[(int) n];
            in.readFully(b);
            text.write(b);
        } while (!fin);
        return text.toString(StandardCharsets.UTF_8);
    }

    private static String line(InputStream in) throws IOException {
        StringBuilder b = new StringBuilder();
        for (int c = in.read(); c != '\n'; c = in.read()) {
            if (c < 0) {
                throw new IOException("closed after \"" + b + "\"");
            }
            if (c != '\r') {
                b.append((char) c);
            }
        }
        return b.toString();
    }
}
