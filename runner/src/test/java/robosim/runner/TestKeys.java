package robosim.runner;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import robosim.protocol.SimulationKeys;

/**
 * Simulation keys for tests, made by {@code scripts/make-keys.sh} itself, once per name for the whole build (each
 * run of the script is a keytool JVM: a second or so of a core): under {@code target/test-keys/NAME}, made by the
 * first test JVM that asks, under a file lock the other test JVMs wait on, and copied into the fresh directory a
 * test asks for. Keys of different names differ, as a test's "keys" and "others" must.
 */
final class TestKeys {
    /** Where the keys of each name are kept for the build (the runner module's target, cleaned with it). */
    private static final Path KEPT = Path.of("target", "test-keys").toAbsolutePath();

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

    /** The keys of {@code name}, made by the script the first time any test JVM of this build asks for them. */
    private static synchronized Path made(String name) throws IOException, InterruptedException {
        Path dir = KEPT.resolve(name);
        Files.createDirectories(KEPT);
        try (java.nio.channels.FileChannel lock = java.nio.channels.FileChannel.open(KEPT.resolve(".lock"),
                java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.WRITE);
                java.nio.channels.FileLock held = lock.lock()) {
            if (Files.isRegularFile(dir.resolve("simulation.p12"))) {
                return dir; // (made whole by an earlier JVM: it is moved into place only once made)
            }
            Path tmp = Files.createTempDirectory(KEPT, name + ".");
            Path making = tmp.resolve(name);
            Process p = new ProcessBuilder("bash", "../scripts/make-keys.sh", making.toString())
                    .redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!p.waitFor(120, TimeUnit.SECONDS) || p.exitValue() != 0) {
                throw new IOException("make-keys.sh failed: " + out);
            }
            if (!Files.isRegularFile(making.resolve("simulation.p12"))) {
                throw new IOException("make-keys.sh made no key pair: " + out);
            }
            Files.move(making, dir, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
            Files.delete(tmp);
            return dir;
        }
    }

    /** New keys under {@code parent}, loaded. */
    static SimulationKeys keys(Path parent, String name) throws IOException, InterruptedException {
        return SimulationKeys.fromDirectory(make(parent, name));
    }
}
