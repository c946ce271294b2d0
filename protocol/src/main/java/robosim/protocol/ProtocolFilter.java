package robosim.protocol;

import java.io.ObjectInputFilter;
import java.util.Set;

/**
 * The allow-list on every object input stream: only the protocol's own message classes, at most
 * {@link #MAX_DEPTH} deep, no arrays longer than {@link #MAX_ARRAY_LENGTH} and at most
 * {@link #MAX_REFERENCES_PER_MESSAGE} objects read for one message. The JDK's reference count is a
 * running total over the stream's life (a reset does not lower it), so the bound is measured from
 * where the current message began ({@link #beginMessage}). One instance per stream: it remembers why
 * it last refused, for the connection's error message.
 */
public final class ProtocolFilter implements ObjectInputFilter {
    public static final Set<Class<?>> MESSAGE_CLASSES = Set.of(
            RobotHello.class, RobotWelcome.class, StepRequest.class, StepResponse.class,
            GeometryHello.class, GeometryWorld.class, GeometryStepRequest.class, GeometryStepResponse.class,
            ViewerHello.class, WorldSnapshot.class, PoseUpdate.class, RobotView.class, RunState.class, SimulationEnd.class,
            Challenge.class, Proof.class, SharedHello.class, SharedRequests.class, SharedReplies.class);
    /** Messages are flat: one object, its fields written inline. */
    public static final long MAX_DEPTH = 2;
    /** No message sends an array object; primitive arrays up to this length are tolerated. */
    public static final long MAX_ARRAY_LENGTH = 1 << 16;
    /** Protocol messages are one object each; this leaves room and stops a reference flood. */
    public static final long MAX_REFERENCES_PER_MESSAGE = 1_000;

    private final long maxReferencesPerMessage;
    private boolean messageStart = true;
    /** The message classes the reader takes now (checked before a message is built, so none it refuses allocates). */
    private Set<Class<?>> expected = MESSAGE_CLASSES;
    private long referencesAtStart;
    private volatile String lastRejection = "";

    public ProtocolFilter() {
        this(MAX_REFERENCES_PER_MESSAGE);
    }

    ProtocolFilter(long maxReferencesPerMessage) {
        this.maxReferencesPerMessage = maxReferencesPerMessage;
    }

    /** Called by the reader before each message: references are counted from here; any message class is taken. */
    public void beginMessage() {
        beginMessage(MESSAGE_CLASSES);
    }

    /**
     * Called by the reader before a message that must be one of {@code kinds}: a message of any other class is
     * refused as its class is read, before its fields are (a stranger's counts allocate nothing).
     */
    public void beginMessage(Set<Class<?>> kinds) {
        expected = kinds;
        messageStart = true;
    }

    @Override
    public Status checkInput(FilterInfo info) {
        if (info.depth() > MAX_DEPTH) {
            return reject("object graph deeper than " + MAX_DEPTH + ": " + info.depth());
        }
        if (messageStart) {
            referencesAtStart = info.references();
            messageStart = false;
        }
        long inMessage = info.references() - referencesAtStart;
        if (inMessage > maxReferencesPerMessage) {
            return reject("more than " + maxReferencesPerMessage + " objects in one message: " + inMessage);
        }
        Class<?> c = info.serialClass();
        if (c == null) {
            return Status.ALLOWED;
        }
        if (c.isArray()) {
            if (!c.getComponentType().isPrimitive()) {
                return reject("array of " + c.getComponentType().getName() + " is not a protocol type");
            }
            if (info.arrayLength() > MAX_ARRAY_LENGTH) {
                return reject("array length exceeds " + MAX_ARRAY_LENGTH + ": " + info.arrayLength());
            }
            return Status.ALLOWED;
        }
        if (MESSAGE_CLASSES.contains(c)) {
            if (info.depth() == 1 && !expected.contains(c)) {
                return reject("expected " + expectedNames() + ", got a " + c.getSimpleName());
            }
            return Status.ALLOWED;
        }
        return reject("class " + c.getName() + " is not a protocol message");
    }

    private String expectedNames() {
        if (expected.size() > 3) {
            return "a protocol message";
        }
        return "a " + String.join(" or a ", expected.stream().map(Class::getSimpleName).sorted().toList());
    }

    private Status reject(String why) {
        lastRejection = why;
        return Status.REJECTED;
    }

    /** Why this filter last refused something, or "" if it never did. */
    public String lastRejection() {
        return lastRejection;
    }
}
