package robosim.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.io.InvalidClassException;
import java.io.ObjectInputStream;
import java.io.ObjectStreamClass;

/**
 * The object input stream of every connection and recording: the {@link ProtocolFilter}, and before it a
 * check by name. The JDK loads a class a stream names (and builds a proxy class for a proxy descriptor)
 * before the filter sees it, and loading a class of the class path that this JVM cannot link throws an
 * Error, not an exception a reader handles (found by fuzzing: a proxy of an interface built for a newer
 * JDK); so only the message classes and primitive arrays are ever loaded, and no proxy class at all.
 */
final class ProtocolInputStream extends ObjectInputStream implements RecordingVersion {
    private static final String PRIMITIVE_ARRAYS = "ZBCSIJFD";
    /** The most of a refused class's name a refusal repeats. */
    private static final int MAX_NAME = 100;

    /** The recording version it reads a frame of, or {@link RecordingFormat#VERSION} (a connection's). */
    private final int recordingVersion;

    ProtocolInputStream(InputStream in, ProtocolFilter filter) throws IOException {
        this(in, filter, RecordingFormat.VERSION);
    }

    /** A stream of a frame of a recording of {@code version}: its messages as that version wrote them. */
    ProtocolInputStream(InputStream in, ProtocolFilter filter, int recordingVersion) throws IOException {
        super(in);
        setObjectInputFilter(filter);
        this.recordingVersion = recordingVersion;
    }

    @Override
    public int recordingVersion() {
        return recordingVersion;
    }

    @Override
    protected Class<?> resolveClass(ObjectStreamClass desc) throws IOException, ClassNotFoundException {
        String name = desc.getName();
        if (name.length() == 2 && name.charAt(0) == '[' && PRIMITIVE_ARRAYS.indexOf(name.charAt(1)) >= 0) {
            return super.resolveClass(desc);
        }
        for (Class<?> c : ProtocolFilter.MESSAGE_CLASSES) {
            if (c.getName().equals(name)) {
                return c;
            }
        }
        name = name.length() > MAX_NAME ? name.substring(0, MAX_NAME) + "..." : name; // (it goes into log lines)
        if (name.startsWith("[")) {
            String component = name.substring(1);
            throw new InvalidClassException("array of " + (component.startsWith("L") && component.endsWith(";")
                    ? component.substring(1, component.length() - 1) : component) + " is not a protocol type");
        }
        throw new InvalidClassException("class " + name + " is not a protocol message");
    }

    @Override
    protected Class<?> resolveProxyClass(String[] interfaces) throws IOException {
        throw new InvalidClassException("a proxy class is not a protocol message");
    }
}
