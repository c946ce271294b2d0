package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.protocol.PoseUpdate;
import robosim.web.WebViewerServer;

/**
 * The browser viewer's server ({@code --web-port}) beside a running 10-robot simulation: its page and
 * three.js come from the jar, its WebSocket feed gives the world and then steps whose poses are the
 * run's, a page may pause but not stop, and a request naming another host or a WebSocket from another
 * origin is refused.
 */
class WebViewerTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final long LONG_S = 120;

    @Test
    void thePageAndItsFeedShowTheRun() throws Exception {
        List<JsonNode> got = new CopyOnWriteArrayList<>();
        java.util.concurrent.CountDownLatch pageHasTheWorld = new java.util.concurrent.CountDownLatch(1);
        CompletableFuture<Void> ended = new CompletableFuture<>();
        WebViewerServer[] web = new WebViewerServer[1];
        InJvmSimulation sim = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml")).sideline((env, ports) -> {
            web[0] = new WebViewerServer("127.0.0.1", ports[1], null, (verb, arg) -> "{\"ok\":true,\"message\":\"" + verb + "\"}");
            web[0].start(java.net.InetAddress.getLoopbackAddress(), 0);
            HttpClient http = HttpClient.newHttpClient();
            String base = "http://localhost:" + web[0].port();
            assertEquals(200, http.send(HttpRequest.newBuilder(URI.create(base + "/")).build(),
                    HttpResponse.BodyHandlers.ofString()).statusCode());
            HttpResponse<String> three = http.send(HttpRequest.newBuilder(URI.create(base + "/three/three.module.min.js"))
                    .build(), HttpResponse.BodyHandlers.ofString());
            assertEquals(200, three.statusCode());
            assertTrue(three.body().length() > 100_000, "three.js from the jar");
            assertEquals(404, http.send(HttpRequest.newBuilder(URI.create(base + "/../pom.xml")).build(),
                    HttpResponse.BodyHandlers.ofString()).statusCode());
            http.newWebSocketBuilder().header("Origin", base).buildAsync(URI.create("ws://localhost:" + web[0].port()
                    + "/ws"), new WebSocket.Listener() {
                        private final StringBuilder part = new StringBuilder();

                        @Override
                        public CompletionStage<?> onText(WebSocket ws, CharSequence data, boolean last) {
                            part.append(data);
                            if (last) {
                                try {
                                    JsonNode m = JSON.readTree(part.toString());
                                    got.add(m);
                                    if (m.path("type").asText().equals("snapshot")) { // (the robot panel)
                                        ws.sendText("watch nobody", true);
                                        ws.sendText("watch " + m.path("robots").get(0).path("name").asText(), true);
                                    }
                                    if (m.path("type").asText().equals("watchStarted")) {
                                        pageHasTheWorld.countDown(); // (and the robot panel's feed has joined)
                                    }
                                    if (m.path("type").asText().equals("end")) {
                                        ws.sendText("pause", true);
                                        ws.sendText("stop", true);
                                    }
                                    if (got.stream().filter(r -> r.has("request")).count() == 4) {
                                        ended.complete(null); // (all four replies are in)
                                    }
                                } catch (Exception e) {
                                    ended.completeExceptionally(e);
                                }
                                part.setLength(0);
                            }
                            ws.request(1);
                            return null;
                        }
                    }).get(LONG_S, TimeUnit.SECONDS);
        }).run(2000, true, () -> robot -> { // (the run starts once the page has the world: it sees every step,
            // and once its robot panel's feed has joined: it sees the robot's every step)
            try {
                pageHasTheWorld.await(50, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            new Chatter().run(robot);
        });
        try {
            ended.get(LONG_S, TimeUnit.SECONDS);
            assertEquals("snapshot", got.get(0).path("type").asText(), got.get(0).toString());
            assertEquals(10, got.get(0).path("robots").size());
            long last = -2;
            int updates = 0;
            for (JsonNode m : got) {
                if (m.path("type").asText().equals("update")) {
                    updates++;
                    long step = m.path("step").asLong();
                    assertTrue(step > last, "steps advance: " + step + " after " + last);
                    last = step;
                    PoseUpdate u = sim.updates.get((int) step);
                    for (int i = 0; i < u.count(); i++) {
                        assertEquals(u.xMm(i), m.path("x").get(i).asDouble(), "x of robot " + i + " at step " + step);
                        assertEquals(u.yMm(i), m.path("y").get(i).asDouble(), "y of robot " + i + " at step " + step);
                        assertEquals(u.headingDeg(i), m.path("heading").get(i).asDouble());
                    }
                }
            }
            assertTrue(updates > 0, "the page saw the run: " + got);
            assertEquals(1999, last, "and its last step");
            JsonNode pause = reply(got, "pause");
            JsonNode stop = reply(got, "stop");
            assertTrue(pause.path("ok").asBoolean(), pause.toString());
            assertFalse(stop.path("ok").asBoolean(), "a page may not stop the run: " + stop);
            List<JsonNode> watches = got.stream().filter(m -> m.path("request").asText().equals("watch")).toList();
            assertEquals("no robot of this run is called nobody", watches.get(0).path("error").asText(), got.toString());
            assertTrue(watches.get(1).path("ok").asBoolean(), watches.get(1).toString());
            // the robot panel's feed: the watched robot's views, each with the messages since the one before
            String watched = sim.spec.robots().get(0).name();
            long viewStep = -1;
            long next = -1;
            int views = 0;
            for (JsonNode m : got) {
                if (m.path("type").asText().equals("view")) {
                    views++;
                    assertEquals(watched, m.path("name").asText());
                    assertTrue(m.path("step").asLong() > viewStep && m.path("since").asLong() > viewStep, m.toString());
                    viewStep = m.path("step").asLong();
                    if (m.path("leftOut").asInt() > 0) {
                        next = -1; // (more than a view carries came since the last: it says how many, and the newest)
                    }
                    for (JsonNode d : m.path("delivered")) {
                        long n = Long.parseLong(d.path("text").asText());
                        assertTrue(next < 0 || n == next, "its inbox whole, in order: " + n + " where " + next + " was due");
                        next = n + 1;
                    }
                }
            }
            assertTrue(views > 0 && next > 0, "the page saw the robot's own steps: " + views + " views");

            HttpClient http = HttpClient.newHttpClient();
            String base = "http://localhost:" + web[0].port();
            try (java.net.Socket s = new java.net.Socket("127.0.0.1", web[0].port())) { // (HttpClient sets Host itself)
                s.getOutputStream().write("GET / HTTP/1.1\r\nHost: evil.example\r\n\r\n".getBytes(
                        java.nio.charset.StandardCharsets.US_ASCII));
                String status = new java.io.BufferedReader(new java.io.InputStreamReader(s.getInputStream(),
                        java.nio.charset.StandardCharsets.US_ASCII)).readLine();
                assertTrue(status.startsWith("HTTP/1.1 421"), "a rebound DNS name gets nothing: " + status);
            }
            CompletableFuture<WebSocket> other = http.newWebSocketBuilder().header("Origin", "http://evil.example")
                    .buildAsync(URI.create("ws://localhost:" + web[0].port() + "/ws"), new WebSocket.Listener() { });
            Exception refused = org.junit.jupiter.api.Assertions.assertThrows(Exception.class,
                    () -> other.get(LONG_S, TimeUnit.SECONDS));
            assertTrue(refused.getCause() instanceof java.net.http.WebSocketHandshakeException h
                    && h.getResponse().statusCode() == 403, "a WebSocket from another origin is refused: " + refused);
        } finally {
            if (web[0] != null) {
                web[0].close();
            }
        }
    }

    private static JsonNode reply(List<JsonNode> got, String request) {
        return got.stream().filter(m -> m.path("request").asText().equals(request)).findFirst()
                .orElseThrow(() -> new AssertionError("no reply to " + request + ": " + got));
    }
}
