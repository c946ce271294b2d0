package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/** Client -> Environment, the answer to a {@link Challenge}: an HMAC of the nonce under the shared secret. */
public final class Proof implements java.io.Externalizable {
    /** An HMAC-SHA256's length, bytes. */
    public static final int MAC_BYTES = 32;

    private byte[] mac = new byte[MAC_BYTES];

    public Proof() {
    }

    public Proof(byte[] mac) {
        if (mac.length != MAC_BYTES) {
            throw new IllegalArgumentException("a proof has " + MAC_BYTES + " bytes, got " + mac.length);
        }
        this.mac = mac.clone();
    }

    public byte[] mac() {
        return mac.clone();
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.write(mac);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        in.readFully(mac);
    }
}
