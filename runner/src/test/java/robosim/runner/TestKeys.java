package robosim.runner;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import robosim.protocol.SimulationKeys;

/**
 * Simulation keys for tests, made by {@code scripts/make-keys.sh} itself, once per name in each test JVM (each run
 * of the script is a keytool JVM: a second or so of a core), and copied into the fresh directory a test asks for.
 * Keys of different names differ, as a test's "keys" and "others" must.
 */
final class TestKeys {
    /** The keys made so far in this JVM, by name, in a directory of their own. */
    private static final java.util.Map<String, Path> MADE = new java.util.HashMap<>();

    private TestKeys() {
    }

    /** Makes a new keys directory under {@code parent} (it must not exist yet) and returns it. */
    static Path make(Path parent, String name) throws IOException, InterruptedException {
        Path made = made(name);
        Path dir = parent.resolve(name);
        Files.createDirectory(dir, java.nio.file.attribute.PosixFilePermissions.asFileAttribute(
                java.nio.file.attribute.PosixFilePermissions.fromString("rwx------"))); // (as the script makes it)
        try (var files = Files.list(made)) {
            for (Path f : files.toList()) {
                Files.copy(f, dir.resolve(f.getFileName()), java.nio.file.StandardCopyOption.COPY_ATTRIBUTES);
            }
        }
        return dir;
    }

    /** The keys of {@code name}, made by the script the first time they are asked for in this JVM. */
    private static synchronized Path made(String name) throws IOException, InterruptedException {
        Path cached = MADE.get(name);
        if (cached != null) {
            return cached;
        }
        Path tmp = Files.createTempDirectory("robosim-test-keys");
        Path dir = tmp.resolve(name);
        tmp.toFile().deleteOnExit(); // (deleted last: files registered later go first)
        dir.toFile().deleteOnExit();
        Process p = new ProcessBuilder("bash", "../scripts/make-keys.sh", dir.toString())
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(120, TimeUnit.SECONDS) || p.exitValue() != 0) {
            throw new IOException("make-keys.sh failed: " + out);
        }
        if (!Files.isRegularFile(dir.resolve("simulation.p12"))) {
            throw new IOException("make-keys.sh made no key pair: " + out);
        }
        try (var files = Files.list(dir)) {
            files.forEach(f -> f.toFile().deleteOnExit());
        }
        MADE.put(name, dir);
        return dir;
    }

    /** New keys under {@code parent}, loaded. */
    static SimulationKeys keys(Path parent, String name) throws IOException, InterruptedException {
        return SimulationKeys.fromDirectory(make(parent, name));
    }
}
