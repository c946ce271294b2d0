package robosim.environment.control;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.net.RunStatus;

/**
 * What each control-port request does, and its JSON reply ({@code {"ok":true,...}} or
 * {@code {"ok":false,"error":"..."}}): {@code token SECRET}, {@code status}, {@code start}, {@code stop},
 * {@code pause}, {@code resume}, {@code step N}, {@code load FILE} (only under the
 * {@link EnvironmentDirectories}), {@code shutdown}. Called by the control threads, one request of a
 * connection at a time; a bad request gets an error reply and never touches the simulation.
 */
final class ControlRequests {
    private static final Logger LOG = LoggerFactory.getLogger(ControlRequests.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    /** How long a waiting request (step N, pause) may take before it answers anyway, s. */
    private static final long WAIT_S = 600;

    /** One connection's standing: whether it has given the token. */
    static final class Caller {
        volatile boolean authorised;
    }

    private final EnvironmentHost host;
    private final String token;
    private final EnvironmentDirectories directories;

    ControlRequests(EnvironmentHost host, String token, EnvironmentDirectories directories) {
        this.host = host;
        this.token = token;
        this.directories = directories;
    }

    Caller caller() {
        Caller c = new Caller();
        c.authorised = token == null;
        return c;
    }

    /** The request's verb, lower case. */
    static String verb(String request) {
        return request.split("\\s+", 2)[0].toLowerCase(Locale.ROOT);
    }

    /** True for the requests that may wait (on the simulation or a file): they run on the {@code control} thread. */
    static boolean waits(String verb) {
        return verb.equals("step") || verb.equals("pause") || verb.equals("start") || verb.equals("load");
    }

    ObjectNode handle(Caller caller, String request) {
        String[] w = request.split("\\s+", 2);
        String verb = verb(request);
        String arg = w.length > 1 ? w[1].strip() : "";
        try {
            if (verb.equals("token")) {
                caller.authorised = token == null || MessageDigest.isEqual(token.getBytes(StandardCharsets.UTF_8),
                        arg.getBytes(StandardCharsets.UTF_8));
                if (!caller.authorised) {
                    LOG.warn("control port: a wrong token was given");
                }
                return caller.authorised ? ok("authorised") : error("wrong token");
            }
            if (!caller.authorised) {
                return error("a token is required first: token SECRET");
            }
            return switch (verb) {
                case "status" -> status();
                case "start" -> ok(host.start());
                case "resume" -> {
                    host.current().resume();
                    yield ok("running");
                }
                case "pause" -> {
                    host.current().pause(WAIT_S, TimeUnit.SECONDS);
                    yield ok("paused at step " + host.current().status().step());
                }
                case "step" -> {
                    long n = steps(arg);
                    long at = host.current().step(n, WAIT_S, TimeUnit.SECONDS);
                    yield ok("paused at step " + at);
                }
                case "stop" -> ok(host.stop());
                case "load" -> {
                    if (arg.isEmpty()) {
                        yield error("load needs a file: load FILE");
                    }
                    yield ok(host.load(directories.resolve(arg)));
                }
                case "shutdown" -> ok(host.shutdown());
                default -> error("unknown request \"" + abbreviate(verb) + "\" (requests: status, start, stop, "
                        + "pause, resume, step N, load FILE, shutdown, token SECRET)");
            };
        } catch (EnvironmentFileException | IllegalArgumentException | IOException e) {
            return error(abbreviate(e.getMessage(), 400));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return error("interrupted");
        } catch (RuntimeException e) {
            LOG.warn("control port: {} failed", abbreviate(request), e);
            return error("failed: " + e);
        }
    }

    private static long steps(String arg) {
        try {
            long n = Long.parseLong(arg);
            if (n < 1) {
                throw new NumberFormatException();
            }
            return n;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("step needs a positive whole number of steps, got \""
                    + abbreviate(arg) + "\"");
        }
    }

    private ObjectNode status() {
        RunStatus s = host.current().status();
        ObjectNode n = ok(null);
        n.put("state", s.state().name());
        n.put("step", s.step());
        n.put("steps_per_s", Math.round(s.stepsPerSecond() * 10) / 10.0);
        n.put("file", String.valueOf(host.file()));
        n.putPOJO("robots", s.robots());
        n.putPOJO("connected", s.connected());
        n.putPOJO("left", s.left());
        n.put("geometry", s.geometry());
        n.put("viewers", s.viewers());
        if (!s.reason().isEmpty()) {
            n.put("reason", s.reason());
        }
        return n;
    }

    static ObjectNode ok(String message) {
        ObjectNode n = JSON.createObjectNode();
        n.put("ok", true);
        if (message != null) {
            n.put("message", message);
        }
        return n;
    }

    static ObjectNode error(String message) {
        ObjectNode n = JSON.createObjectNode();
        n.put("ok", false);
        n.put("error", message);
        return n;
    }

    /** Network text made safe for a log line or a reply: control characters as '?', at most 40 characters. */
    static String abbreviate(String s) {
        return abbreviate(s, 40);
    }

    private static String abbreviate(String s, int max) {
        String clean = String.valueOf(s).replaceAll("\\p{Cntrl}", "?");
        return clean.length() > max ? clean.substring(0, max) + "..." : clean;
    }
}
