package robosim.environment.net;

import robosim.environment.run.LoopHook;
import java.util.ArrayList;
import java.util.List;

/**
 * The shared connections the loop has put something into since it last wrote, the {@link LoopHook} of that
 * transport: after each event (and each deadline check) the loop writes one frame to each, so a step's responses
 * to every robot of a process go out in one write. Loop thread only.
 */
final class SharedOutput implements LoopHook {
    private final List<SharedConnection> pending = new ArrayList<>();

    /** {@code c} has a frame to write. */
    void add(SharedConnection c) {
        pending.add(c);
    }

    /** Writes every pending frame. */
    @Override
    public void flush() {
        if (pending.isEmpty()) {
            return;
        }
        for (int i = 0; i < pending.size(); i++) {
            pending.get(i).flush();
        }
        pending.clear();
    }
}
