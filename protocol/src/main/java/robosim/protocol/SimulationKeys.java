package robosim.protocol;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * What a simulation's processes know that strangers do not: the shared secret, and (when made into a
 * directory by {@code scripts/make-keys.sh}) the simulation's TLS key pair ({@link Tls}). Every client
 * proves the secret by challenge and response, never sending it: after a client's hello the Environment sends a {@link Challenge} (a fresh random nonce) and the
 * client answers with a {@link Proof}, HMAC-SHA256 under the secret of the nonce and the client's role
 * (robot, viewer, geometry), compared in constant time. A proof is good for one nonce only, so a
 * recorded one cannot be replayed. Every process takes its keys from its environment, never from its
 * command line (which {@code ps} shows): {@code ROBOSIM_KEYS} (the directory {@code scripts/make-keys.sh}
 * makes: the secret and the key pair, for TLS on every connection), else the secret alone from
 * {@code ROBOSIM_SECRET_FILE} (a file holding it) or {@code ROBOSIM_SECRET} (no TLS: loopback only).
 * Immutable; any thread.
 */
public final class SimulationKeys {
    /** The shortest secret taken, characters. */
    public static final int MIN_CHARS = 16;
    private static final SecureRandom RANDOM = new SecureRandom();

    /** In a keys directory, the file holding the secret. */
    public static final String SECRET_FILE = "secret";
    private static final int MAX_SECRET_FILE_BYTES = 4096;

    private final byte[] key;
    private final Tls tls;

    private SimulationKeys(byte[] key, Tls tls) {
        this.key = key;
        this.tls = tls;
    }

    /** {@code text} (surrounding white space dropped) as a secret; {@code source} names it in the error. */
    public static SimulationKeys of(String text, String source) throws IOException {
        String t = text.strip();
        if (t.length() < MIN_CHARS) {
            throw new IOException(source + ": the shared secret must have at least " + MIN_CHARS
                    + " characters, it has " + t.length());
        }
        return new SimulationKeys(t.getBytes(StandardCharsets.UTF_8), null);
    }

    /**
     * The keys in {@code dir}, as {@code scripts/make-keys.sh} makes them: the secret ({@value #SECRET_FILE})
     * and the key pair ({@value Tls#KEY_STORE_FILE}, locked with the secret).
     *
     * @throws IOException naming the file and what is wrong with it
     */
    public static SimulationKeys fromDirectory(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            throw new IOException("ROBOSIM_KEYS " + dir + ": not a directory (scripts/make-keys.sh DIR makes one)");
        }
        Path file = dir.resolve(SECRET_FILE);
        String text = readSecretFile(file, "ROBOSIM_KEYS " + file);
        SimulationKeys secret = of(text, "ROBOSIM_KEYS " + file);
        return new SimulationKeys(secret.key, Tls.load(dir.resolve(Tls.KEY_STORE_FILE), text.strip().toCharArray()));
    }

    private static String readSecretFile(Path p, String source) throws IOException {
        if (!Files.isRegularFile(p) || Files.size(p) > MAX_SECRET_FILE_BYTES) {
            throw new IOException(source + ": not a regular file of at most " + MAX_SECRET_FILE_BYTES + " bytes");
        }
        return Files.readString(p, StandardCharsets.UTF_8);
    }

    /** TLS with the simulation's key pair, or null when these keys are a secret only. */
    public Tls tls() {
        return tls;
    }

    /**
     * This process's keys: the directory {@code ROBOSIM_KEYS} names, else the secret alone from the file
     * {@code ROBOSIM_SECRET_FILE} names or from {@code ROBOSIM_SECRET}, else null (none: only for loopback).
     */
    public static SimulationKeys fromEnvironment() throws IOException {
        synchronized (SimulationKeys.class) { // once per process: the key store costs a key derivation to open
            if (!loadedFromEnvironment) {
                fromEnvironment = loadFromEnvironment();
                loadedFromEnvironment = true;
            }
            return fromEnvironment;
        }
    }

    /** This process's keys, once loaded (guarded by the class). */
    private static SimulationKeys fromEnvironment;
    private static boolean loadedFromEnvironment;

    private static SimulationKeys loadFromEnvironment() throws IOException {
        String dir = System.getenv("ROBOSIM_KEYS");
        if (dir != null && !dir.isEmpty()) {
            return fromDirectory(Path.of(dir));
        }
        String file = System.getenv("ROBOSIM_SECRET_FILE");
        if (file != null && !file.isEmpty()) {
            String source = "ROBOSIM_SECRET_FILE " + file;
            return of(readSecretFile(Path.of(file), source), source);
        }
        String text = System.getenv("ROBOSIM_SECRET");
        return text == null || text.isEmpty() ? null : of(text, "ROBOSIM_SECRET");
    }

    /** A fresh random nonce for one {@link Challenge}. */
    public static byte[] nonce() {
        byte[] n = new byte[Challenge.NONCE_BYTES];
        RANDOM.nextBytes(n);
        return n;
    }

    /** The proof of {@code role} for {@code nonce}. */
    public byte[] prove(String role, byte[] nonce) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key, "HmacSHA256"));
            mac.update(("robosim challenge v1\0" + role + "\0").getBytes(StandardCharsets.UTF_8));
            return mac.doFinal(nonce);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is part of every JDK", e);
        }
    }

    /** True if {@code proof} is {@code role}'s proof for {@code nonce} (constant time). */
    public boolean proves(String role, byte[] nonce, byte[] proof) {
        return MessageDigest.isEqual(prove(role, nonce), proof);
    }

    @Override
    public String toString() {
        return "SimulationKeys[secret hidden" + (tls == null ? ", no TLS]" : ", TLS]");
    }
}
