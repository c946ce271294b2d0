package robosim.environment.control;

import java.io.IOException;
import robosim.protocol.SimulationKeys;
import robosim.web.WebViewerServer;

/** {@code --web-port}: the browser viewer beside an Environment or a replay, its page's requests served in-process. */
public final class WebViewers {
    private WebViewers() {
    }

    /** Before anything listens: {@code --web-port} with a shared secret but no key pair is one line's refusal. */
    public static void check(int webPort, SimulationKeys keys) throws IOException {
        if (webPort >= 0 && keys != null && keys.tls() == null) { // (a browser cannot answer the secret's challenge)
            throw new IOException("--web-port needs the simulation's key pair when there is a shared secret: set "
                    + "ROBOSIM_KEYS to a directory made by scripts/make-keys.sh");
        }
    }

    /**
     * Starts the browser viewer on {@code webPort} on {@code bind} (over TLS with the keys' key pair), fed from
     * this process's viewer port (on {@code bind} too).
     *
     * @throws IOException naming the port if it cannot listen, or keys without a key pair
     */
    public static WebViewerServer start(int webPort, java.net.InetAddress bind, int viewerPort, SimulationKeys keys,
            ControlCommands commands) throws IOException {
        check(webPort, keys);
        String viewerHost = (bind.isAnyLocalAddress() ? java.net.InetAddress.getLoopbackAddress() : bind).getHostAddress();
        WebViewerServer web = new WebViewerServer(viewerHost, viewerPort, keys, (verb, arg) -> {
            com.fasterxml.jackson.databind.node.ObjectNode n = commands.handle(verb, arg);
            return n == null ? ControlReplies.error("not here: " + verb).toString() : n.toString();
        });
        web.start(bind, webPort);
        return web;
    }
}
