package robosim.environment.control;

import java.io.IOException;
import robosim.protocol.SimulationKeys;
import robosim.web.WebViewerServer;

/** {@code --web-port}: the browser viewer beside an Environment or a replay, its page's requests served in-process. */
public final class WebViewers {
    private WebViewers() {
    }

    /**
     * Starts the browser viewer on {@code webPort} on {@code bind} (over TLS with the keys' key pair), fed from
     * this process's viewer port (on {@code bind} too); the port and the keys passed {@code WebPortOption}'s check.
     *
     * @throws IOException naming the port if it cannot listen
     */
    public static WebViewerServer start(int webPort, java.net.InetAddress bind, int viewerPort, SimulationKeys keys,
            ControlCommands commands) throws IOException {
        String viewerHost = (bind.isAnyLocalAddress() ? java.net.InetAddress.getLoopbackAddress() : bind).getHostAddress();
        WebViewerServer web = new WebViewerServer(viewerHost, viewerPort, keys, (verb, arg) -> {
            com.fasterxml.jackson.databind.node.ObjectNode n = commands.handle(verb, arg);
            return n == null ? ControlReplies.error("not here: " + verb).toString() : n.toString();
        });
        web.start(bind, webPort);
        return web;
    }
}
