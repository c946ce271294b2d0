package robosim.runner;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import robosim.protocol.SimulationKeys;

/** Simulation keys for tests, made by {@code scripts/make-keys.sh} itself into a fresh directory. */
final class TestKeys {
    private TestKeys() {
    }

    /** Makes a new keys directory under {@code parent} (the script refuses an existing one) and returns it. */
    static Path make(Path parent, String name) throws IOException, InterruptedException {
        Path dir = parent.resolve(name);
        Process p = new ProcessBuilder("bash", "../scripts/make-keys.sh", dir.toString())
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(120, TimeUnit.SECONDS) || p.exitValue() != 0) {
            throw new IOException("make-keys.sh failed: " + out);
        }
        if (!Files.isRegularFile(dir.resolve("simulation.p12"))) {
            throw new IOException("make-keys.sh made no key pair: " + out);
        }
        return dir;
    }

    /** New keys under {@code parent}, loaded. */
    static SimulationKeys keys(Path parent, String name) throws IOException, InterruptedException {
        return SimulationKeys.fromDirectory(make(parent, name));
    }
}
