package robosim.control;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.protocol.CommandLines;
import robosim.protocol.SimulationKeys;

/**
 * The Control Panel: with no request, a window; with one, a command line for scripts:
 * {@code control-panel.sh HOST [PORT] REQUEST} (the requests are listed in {@code --help}).
 * Prints the reply as {@code key=value} lines; exits 0 if the Environment said ok, 1 if it refused,
 * 2 on bad arguments or when it cannot be reached.
 */
@Command(name = "control-panel.sh", mixinStandardHelpOptions = true,
        description = {"Loads, starts, stops, pauses and steps a running Environment (or a replay) through its control "
                + "port: HOST [PORT] [REQUEST...], the port 8100 when it is left out.",
            "Requests: status: the run's state, step, rate, robots, Geometry and viewers; start: resumes, or after the "
                + "end runs the same file again; stop: ends the simulation (every client is told); pause: holds the run "
                + "after the step in progress; resume: runs on; step N: runs N more steps and holds again; load FILE: "
                + "ends the simulation and waits for FILE's robots; shutdown: ends the simulation and the Environment; "
                + "robots: each robot and its state; add NAME TYPE X Y HEADING [CONTROL]: a robot joins the running "
                + "world at X, Y m; remove NAME: takes a robot out of the run for good.",
            "Of a replay also: seek K: shows step K and goes on from there; speed X: X times real time."})
public final class ControlPanelMain implements Callable<Integer> {
    /** The control port when none is given. */
    static final int DEFAULT_PORT = 8100;

    @Parameters(index = "0", paramLabel = "HOST", description = "The Environment's host.")
    String host;

    @Parameters(index = "1..*", paramLabel = "[PORT] [REQUEST...]", arity = "0..*",
            description = "The control port (default: 8100), then a request (see above); no request opens the window.")
    List<String> rest;

    /** The port, once the arguments are read. */
    int port = DEFAULT_PORT;
    /** The request's words, once the arguments are read; empty: the window. */
    List<String> request = List.of();

    @Option(names = "--timeout-s", defaultValue = "600",
            description = "How long to wait for a reply (step N waits for its steps; default: ${DEFAULT-VALUE}).")
    int timeoutS;

    /**
     * Reads {@code rest}: a port first if it is a number (1 to 65535), then the request. Null, or the one-line
     * error for a port out of range.
     */
    String readRest() {
        List<String> words = rest == null ? List.of() : rest;
        if (!words.isEmpty() && words.get(0).matches("[+-]?\\d+")) {
            long p;
            try {
                p = Long.parseLong(words.get(0));
            } catch (NumberFormatException e) {
                p = -1;
            }
            if (p < 1 || p > 65535) {
                return "port must be from 1 to 65535, got " + words.get(0);
            }
            port = (int) p;
            words = words.subList(1, words.size());
        }
        request = List.copyOf(words);
        return null;
    }

    @Override
    public Integer call() throws Exception {
        String bad = readRest();
        if (bad != null) {
            System.err.println("control-panel: " + bad + " (see --help)");
            return 2;
        }
        SimulationKeys keys;
        try {
            keys = SimulationKeys.fromEnvironment();
        } catch (IOException e) {
            System.err.println("control-panel: " + e.getMessage());
            return 2;
        }
        if (request.isEmpty()) {
            if (java.awt.GraphicsEnvironment.isHeadless()) {
                System.err.println("control-panel: no display for the window; give a request instead (see --help)");
                return 2;
            }
            ControlPanelWindow.open(host, port, keys);
            windowOpened = true;
            return 0;
        }
        String line = String.join(" ", request);
        if (request.get(0).equals("load") && request.size() == 2) {
            // the Environment opens the file: give it an absolute path
            line = "load " + Path.of(request.get(1)).toAbsolutePath().normalize();
        }
        try (ControlClient c = new ControlClient(host, port, keys, timeoutS * 1000)) {
            JsonNode reply = c.request(line);
            print(reply);
            return reply.path("ok").asBoolean() ? 0 : 1;
        } catch (IOException e) {
            System.err.println("control-panel: cannot talk to the Environment at " + host + ":" + port + ": "
                    + e.getMessage());
            return 2;
        }
    }

    static void print(JsonNode reply) {
        System.out.print(lines(reply));
    }

    /** The reply as {@code key=value} lines, for scripts. */
    static String lines(JsonNode reply) {
        StringBuilder out = new StringBuilder();
        for (Iterator<Map.Entry<String, JsonNode>> it = reply.fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> f = it.next();
            JsonNode v = f.getValue();
            out.append(f.getKey()).append('=').append(v.isArray() ? join(v) : v.asText()).append(System.lineSeparator());
        }
        return out.toString();
    }

    /** An array's items joined by ","; an object item as its values joined by ":" (robots: name:state[:since]). */
    private static String join(JsonNode array) {
        StringBuilder b = new StringBuilder();
        for (JsonNode n : array) {
            b.append(b.length() == 0 ? "" : ",");
            if (n.isObject()) {
                StringBuilder o = new StringBuilder();
                n.elements().forEachRemaining(e -> o.append(o.length() == 0 ? "" : ":").append(e.asText()));
                b.append(o);
            } else {
                b.append(n.asText());
            }
        }
        return b.toString();
    }

    public static void main(String[] args) {
        CommandLine cl = CommandLines.of("control-panel", new ControlPanelMain());
        int code = cl.execute(args);
        if (!windowOpened) {
            System.exit(code);
        }
    }

    /** True once the window is up: the process then lives until it is closed. */
    private static volatile boolean windowOpened;
}
