package robosim.environment.server;

import picocli.CommandLine.Option;
import robosim.protocol.SimulationKeys;

/**
 * The port of the browser viewer served beside a run or a replay (a picocli mixin of environment.sh, replay.sh,
 * headless.sh and learning-host.sh).
 */
public final class WebPortOption {
    @Option(names = "--web-port", paramLabel = "PORT", defaultValue = "-1", description = "Serve the browser viewer "
            + "on this port, beside the viewer port (default: none; 0: a free one, said on the listening line); over "
            + "TLS to browsers holding the key pair where the simulation has ROBOSIM_KEYS.")
    private int port;

    /** The port, 0 for a free one, or -1: none. */
    public int port() {
        return port;
    }

    /** What is wrong with it, with {@code keys} (null: none), or null. */
    public String problem(SimulationKeys keys) {
        if (port < -1 || port > 65535) {
            return "--web-port must be from 0 to 65535 (-1: none), got " + port;
        }
        if (port >= 0 && keys != null && keys.tls() == null) { // (a browser cannot answer the secret's challenge)
            return "--web-port needs the simulation's key pair when there is a shared secret: set ROBOSIM_KEYS to a "
                    + "directory made by scripts/make-keys.sh";
        }
        return null;
    }
}
