package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Environment -> client, right after the client's hello when the Environment has a shared secret: a
 * fresh random nonce the client must answer with a {@link Proof} ({@link SimulationKeys}).
 */
public final class Challenge implements java.io.Externalizable {
    /** A nonce's length, bytes. */
    public static final int NONCE_BYTES = 32;

    private byte[] nonce = new byte[NONCE_BYTES];

    public Challenge() {
    }

    public Challenge(byte[] nonce) {
        if (nonce.length != NONCE_BYTES) {
            throw new IllegalArgumentException("a nonce has " + NONCE_BYTES + " bytes, got " + nonce.length);
        }
        this.nonce = nonce.clone();
    }

    public byte[] nonce() {
        return nonce.clone();
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.write(nonce);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        in.readFully(nonce);
    }
}
