package robosim.bench;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;

/**
 * Bytes per message, Serializable against Externalizable, in a long-lived stream (class already
 * described). Each message is a fresh object with fresh arrays and lists, as each step's are: writing
 * the same instance again would let default serialization send its nested values as back-references.
 */
public final class MessageSizes {
    private MessageSizes() {
    }

    static int[] sizes(java.util.function.Supplier<Object> make) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ObjectOutputStream out = new ObjectOutputStream(bytes);
        out.flush();
        int header = bytes.size();
        out.writeUnshared(make.get());
        out.flush();
        int first = bytes.size() - header;
        out.writeUnshared(make.get());
        out.flush();
        return new int[] {bytes.size() - header - first, first};
    }

    public static void main(String[] args) throws IOException {
        System.out.println("message   externalizable bytes (first)   serializable bytes (first)");
        for (String m : new String[] {"request", "response"}) {
            int[] e = sizes(() -> SerializationBenchmark.make(m, true));
            int[] s = sizes(() -> SerializationBenchmark.make(m, false));
            System.out.printf("%-9s %6d (%d) %23d (%d)%n", m, e[0], e[1], s[0], s[1]);
        }
    }
}
