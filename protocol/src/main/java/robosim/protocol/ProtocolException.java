package robosim.protocol;

import java.io.IOException;

/** A peer sent something the protocol does not allow; the connection that read it must be closed. */
public class ProtocolException extends IOException {
    private static final long serialVersionUID = 1L;

    public ProtocolException(String message) {
        super(message);
    }
}
