package robosim.environment.control;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.net.RunStatus;
import robosim.protocol.LineProof;
import robosim.protocol.SimulationKeys;

/**
 * What each control-port request does, and its JSON reply ({@code {"ok":true,...}} or
 * {@code {"ok":false,"error":"..."}}): {@code challenge} and {@code prove HEX} (the shared secret's
 * {@link LineProof}, required first when the Environment has keys), {@code status}, {@code start}, {@code stop},
 * {@code pause}, {@code resume}, {@code step N}, {@code load FILE} (only under the
 * {@link EnvironmentDirectories}), {@code shutdown}. Called by the control threads, one request of a
 * connection at a time; a bad request gets an error reply and never touches the simulation.
 */
final class ControlRequests {
    private static final Logger LOG = LoggerFactory.getLogger(ControlRequests.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    /** How long a waiting request (step N, pause) may take before it answers anyway, s. */
    private static final long WAIT_S = 600;

    /** The reply to a request made before the proof. */
    static final String PROVE_FIRST = "prove the shared secret first: challenge, then prove HEX (the Control "
            + "Panel does it when ROBOSIM_KEYS or ROBOSIM_SECRET_FILE is set)";

    /** One connection's standing: whether it has proved the shared secret (one control thread at a time). */
    static final class Caller {
        private final LineProof proof;

        Caller(LineProof proof) {
            this.proof = proof;
        }

        synchronized boolean proven() {
            return proof.proven();
        }
    }

    private final EnvironmentHost host;
    private final SimulationKeys keys;
    private final EnvironmentDirectories directories;

    ControlRequests(EnvironmentHost host, SimulationKeys keys, EnvironmentDirectories directories) {
        this.host = host;
        this.keys = keys;
        this.directories = directories;
    }

    Caller caller() {
        return new Caller(new LineProof(keys, LineProof.CONTROL));
    }

    /** True for the requests a caller may make before it has proved the secret. */
    static boolean beforeProof(String verb) {
        return verb.equals(LineProof.CHALLENGE) || verb.equals(LineProof.PROVE);
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
            if (verb.equals(LineProof.CHALLENGE)) {
                ObjectNode n = ok(null);
                synchronized (caller) {
                    n.put("nonce", caller.proof.challenge());
                }
                return n;
            }
            if (verb.equals(LineProof.PROVE)) {
                boolean proven;
                synchronized (caller) {
                    proven = caller.proof.prove(arg);
                }
                if (!proven) {
                    LOG.warn("control port: a connection did not prove the shared secret");
                }
                return proven ? ok("proven") : error("that is not the proof for the last challenge");
            }
            if (!caller.proven()) {
                return error(PROVE_FIRST);
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
                        + "pause, resume, step N, load FILE, shutdown, challenge, prove HEX)");
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

    static String abbreviate(String s, int max) {
        String clean = String.valueOf(s).replaceAll("\\p{Cntrl}", "?");
        return clean.length() > max ? clean.substring(0, max) + "..." : clean;
    }
}
