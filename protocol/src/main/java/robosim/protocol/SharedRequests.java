package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.Arrays;

/**
 * Robot process -> Environment on a shared connection: the {@link StepRequest}s of some of its robots,
 * each with its slot (its place in the {@link SharedHello}). Each robot's request for a step goes once,
 * in one frame of that step; a process sends every robot's request of the step in one frame, or those
 * ready first and the rest after. The writer reuses one frame ({@link #clear}, {@link #add}).
 */
public final class SharedRequests implements java.io.Externalizable {
    private int count;
    private int[] slots = new int[8];
    private StepRequest[] requests = new StepRequest[8];

    public SharedRequests() {
    }

    /** Empties the frame for the next step (the writer's). */
    public void clear() {
        Arrays.fill(requests, 0, count, null);
        count = 0;
    }

    /** Adds robot {@code slot}'s request (the writer's). */
    public void add(int slot, StepRequest request) {
        if (count == slots.length) {
            slots = Arrays.copyOf(slots, Math.max(8, count * 2));
            requests = Arrays.copyOf(requests, slots.length);
        }
        slots[count] = slot;
        requests[count++] = request;
    }

    public int count() {
        return count;
    }

    public int slot(int i) {
        return slots[i];
    }

    public StepRequest request(int i) {
        return requests[i];
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeInt(count);
        for (int i = 0; i < count; i++) {
            out.writeInt(slots[i]);
            requests[i].writeExternal(out);
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        count = Limits.checkCount("requests in one frame", in.readInt(), Limits.MAX_ROBOTS_PER_CONNECTION);
        slots = new int[count];
        requests = new StepRequest[count];
        for (int i = 0; i < count; i++) {
            slots[i] = in.readInt();
            requests[i] = new StepRequest();
            requests[i].readExternal(in);
        }
    }
}
