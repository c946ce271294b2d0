package robosim.protocol;

import java.util.HexFormat;

/**
 * The shared secret's challenge and response on the line protocols (the control port, a remote-control
 * robot's link): the client asks {@code challenge}, the server answers with a fresh nonce in hex, the
 * client sends {@code prove HEX} (the {@link SimulationKeys#prove proof} for its role and that nonce).
 * Each nonce is good for one try. One per connection; one thread at a time.
 */
public final class LineProof {
    /** What a client sends to be challenged. */
    public static final String CHALLENGE = "challenge";
    /** What a client sends its proof after. */
    public static final String PROVE = "prove";
    /** The role of a Control Panel's proof on the control port. */
    public static final String CONTROL = "control";
    /** The role of a Remote Control's proof on a robot's link. */
    public static final String REMOTE_CONTROL = "remote-control";
    private static final HexFormat HEX = HexFormat.of();

    private final SimulationKeys keys;
    private final String role;
    private byte[] nonce;
    private boolean proven;

    /** A connection's standing for {@code role}; with no keys there is nothing to prove. */
    public LineProof(SimulationKeys keys, String role) {
        this.keys = keys;
        this.role = role;
        this.proven = keys == null;
    }

    public boolean proven() {
        return proven;
    }

    /** A fresh nonce, hex, for the reply to {@code challenge}. */
    public String challenge() {
        nonce = SimulationKeys.nonce();
        return HEX.formatHex(nonce);
    }

    /**
     * Checks {@code proofHex} against the last challenge (which it uses up): true if it is the proof (or
     * there are no keys), false if there was no challenge or the text is not the proof. A connection that
     * has proved the secret once stays proven.
     */
    public boolean prove(String proofHex) {
        byte[] n = nonce;
        nonce = null;
        if (keys == null) {
            return true;
        }
        boolean right;
        try {
            right = n != null && proofHex.length() == 2 * Proof.MAC_BYTES
                    && keys.proves(role, n, HEX.parseHex(proofHex));
        } catch (IllegalArgumentException e) {
            right = false;
        }
        proven |= right;
        return right;
    }

    /** The client's side: the {@code prove} line answering a challenge's {@code nonceHex}. */
    public static String answer(SimulationKeys keys, String role, String nonceHex) throws ProtocolException {
        byte[] n;
        try {
            n = HEX.parseHex(nonceHex);
        } catch (IllegalArgumentException e) {
            throw new ProtocolException("the challenge is not a hex nonce");
        }
        if (n.length != Challenge.NONCE_BYTES) {
            throw new ProtocolException("the challenge is not a " + Challenge.NONCE_BYTES + "-byte nonce");
        }
        return PROVE + " " + HEX.formatHex(keys.prove(role, n));
    }
}
