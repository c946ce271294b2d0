package robosim.environment.control;

import static robosim.environment.control.ControlReplies.abbreviate;
import static robosim.environment.control.ControlReplies.error;
import static robosim.environment.control.ControlReplies.ok;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.Locale;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.config.EnvironmentFileException;
import robosim.protocol.LineProof;
import robosim.protocol.SimulationKeys;

/**
 * A control port's requests and their JSON replies ({@link ControlReplies}): {@code challenge} and
 * {@code prove HEX} (the shared secret's {@link LineProof}, required first when the process has keys), then
 * what its {@link ControlCommands} serve. Called by the control threads, one request of a connection at a
 * time; a bad request gets an error reply and never touches the simulation.
 */
final class ControlRequests {
    private static final Logger LOG = LoggerFactory.getLogger(ControlRequests.class);

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

    private final ControlCommands commands;
    private final SimulationKeys keys;

    ControlRequests(ControlCommands commands, SimulationKeys keys) {
        this.commands = commands;
        this.keys = keys;
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

    /** True for the requests that may wait: they run on the {@code control} thread. */
    boolean waits(String verb) {
        return commands.waits(verb);
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
            ObjectNode n = commands.handle(verb, arg);
            return n != null ? n : error("unknown request \"" + abbreviate(verb) + "\" (requests: "
                    + commands.known() + ", challenge, prove HEX)");
        } catch (EnvironmentFileException e) {
            return error(abbreviate(e.getMessage().replace("\n", "; "), 400)); // (a line per fault: one on the wire)
        } catch (IllegalArgumentException | IOException e) {
            return error(abbreviate(e.getMessage(), 400));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return error("interrupted");
        } catch (Exception e) {
            LOG.warn("control port: {} failed", abbreviate(request), e);
            return error("failed: " + e);
        }
    }
}
