import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * A browser page's network side without the browser, for measuring what the web viewer costs the run
 * itself (scripts/bench-costs.sh): connects to the web viewer's WebSocket as the page does (trying every
 * 100 ms until the server answers), watches one robot as the page's robot panel does, asks for the status
 * once a second, and reads every frame until the connection closes; draws nothing.
 * usage: javac -d bench/classes bench/WebPageReader.java; java -cp bench/classes WebPageReader PORT ROBOT
 */
public class WebPageReader {
    public static void main(String[] args) throws Exception {
        String base = "http://localhost:" + args[0];
        String robot = args[1];
        HttpClient http = HttpClient.newHttpClient();
        CompletableFuture<Void> closed = new CompletableFuture<>();
        long[] frames = new long[1];
        WebSocket.Listener reader = new WebSocket.Listener() {
            private boolean asked;

            @Override
            public CompletionStage<?> onText(WebSocket ws, CharSequence data, boolean last) {
                if (last) {
                    frames[0]++;
                    if (!asked) {
                        asked = true;
                        ws.sendText("watch " + robot, true);
                    }
                }
                ws.request(1);
                return null;
            }

            @Override
            public CompletionStage<?> onClose(WebSocket ws, int status, String reason) {
                closed.complete(null);
                return null;
            }

            @Override
            public void onError(WebSocket ws, Throwable error) {
                closed.complete(null);
            }
        };
        WebSocket ws = null;
        while (ws == null) {
            try {
                ws = http.newWebSocketBuilder().header("Origin", base)
                        .buildAsync(URI.create("ws://localhost:" + args[0] + "/ws"), reader).get(5, TimeUnit.SECONDS);
            } catch (Exception notYet) {
                Thread.sleep(100);
            }
        }
        WebSocket page = ws;
        ScheduledExecutorService status = Executors.newSingleThreadScheduledExecutor();
        status.scheduleAtFixedRate(() -> page.sendText("status", true), 1, 1, TimeUnit.SECONDS);
        closed.join();
        status.shutdownNow();
        System.out.println("frames=" + frames[0]);
    }
}
