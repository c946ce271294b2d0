package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * A message from one robot's control code to another's (the original's COMMEVENT). The
 * Environment fills in {@code from}; {@code to} is a robot name or {@link #EVERYONE}. Written inline.
 */
public record CommEvent(String from, String to, String payload) {
    /** The recipient name that means every other robot (a broadcast). */
    public static final String EVERYONE = "*";

    public CommEvent {
        if (from == null || to == null || payload == null) {
            throw new IllegalArgumentException("CommEvent fields must not be null");
        }
    }

    void write(ObjectOutput out) throws IOException {
        out.writeUTF(from);
        out.writeUTF(to);
        out.writeUTF(payload);
    }

    static CommEvent read(ObjectInput in) throws IOException {
        String from = in.readUTF();
        String to = in.readUTF();
        String payload = in.readUTF();
        return new CommEvent(from, to, payload);
    }
}
