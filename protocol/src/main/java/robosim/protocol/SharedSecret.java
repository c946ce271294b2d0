package robosim.protocol;

import java.io.Externalizable;
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
 * The secret every client of one simulation proves it knows, by challenge and response, never sending
 * it: after a client's hello the Environment sends a {@link Challenge} (a fresh random nonce) and the
 * client answers with a {@link Proof}, HMAC-SHA256 under the secret of the nonce and the client's role
 * (robot, viewer, geometry), compared in constant time. A proof is good for one nonce only, so a
 * recorded one cannot be replayed. Every process takes the secret from its environment, never from its
 * command line (which {@code ps} shows): {@code ROBOSIM_SECRET_FILE} (a file holding it, e.g. made by
 * {@code scripts/make-keys.sh}) or {@code ROBOSIM_SECRET}. Immutable; any thread.
 */
public final class SharedSecret {
    public static final int NONCE_BYTES = 32;
    public static final int MAC_BYTES = 32;
    /** The shortest secret taken, characters. */
    public static final int MIN_CHARS = 16;
    private static final SecureRandom RANDOM = new SecureRandom();

    private final byte[] key;

    private SharedSecret(byte[] key) {
        this.key = key;
    }

    /** {@code text} (surrounding white space dropped) as a secret; {@code source} names it in the error. */
    public static SharedSecret of(String text, String source) throws IOException {
        String t = text.strip();
        if (t.length() < MIN_CHARS) {
            throw new IOException(source + ": the shared secret must have at least " + MIN_CHARS
                    + " characters, it has " + t.length());
        }
        return new SharedSecret(t.getBytes(StandardCharsets.UTF_8));
    }

    /**
     * This process's secret: the file {@code ROBOSIM_SECRET_FILE} names, else {@code ROBOSIM_SECRET}, else
     * null (no secret: only for loopback).
     */
    public static SharedSecret fromEnvironment() throws IOException {
        String file = System.getenv("ROBOSIM_SECRET_FILE");
        if (file != null && !file.isEmpty()) {
            Path p = Path.of(file);
            if (!Files.isRegularFile(p) || Files.size(p) > 4096) {
                throw new IOException("ROBOSIM_SECRET_FILE " + file + ": not a regular file of at most 4096 bytes");
            }
            return of(Files.readString(p, StandardCharsets.UTF_8), "ROBOSIM_SECRET_FILE " + file);
        }
        String text = System.getenv("ROBOSIM_SECRET");
        return text == null || text.isEmpty() ? null : of(text, "ROBOSIM_SECRET");
    }

    /** A fresh random nonce for one {@link Challenge}. */
    public static byte[] nonce() {
        byte[] n = new byte[NONCE_BYTES];
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

    /**
     * The client's side, right after it has sent its hello: reads the Environment's first answer; if it
     * is a {@link Challenge}, answers it with this process's proof (or fails, naming what to set, when
     * {@code secret} is null) and reads the answer after it. Returns that first real answer.
     */
    public static Externalizable answerChallenge(ObjectConnection c, SharedSecret secret, String role)
            throws IOException {
        Externalizable first = c.read(Externalizable.class);
        if (!(first instanceof Challenge challenge)) {
            return first;
        }
        if (secret == null) {
            throw new ProtocolException("the Environment asks for the shared secret: set ROBOSIM_SECRET_FILE (a file "
                    + "holding it) or ROBOSIM_SECRET");
        }
        c.write(new Proof(secret.prove(role, challenge.nonce())));
        c.flush();
        return c.read(Externalizable.class);
    }

    @Override
    public String toString() {
        return "SharedSecret[hidden]";
    }
}
