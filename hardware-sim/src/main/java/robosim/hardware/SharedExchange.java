package robosim.hardware;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.RobotControl;

/**
 * Many robots of one process on one exchange thread (the calling one; each robot's control code still
 * has its own thread): each step it sends every robot's request in world order, those whose control
 * code is ready first, then reads every response in the same order. One robot whose connection fails
 * or whose control code does not yield in time ends alone; the others go on.
 */
final class SharedExchange {
    private static final Logger LOG = LoggerFactory.getLogger(SharedExchange.class);
    /** How long the send phase waits for one control code before looking whether the step went on. */
    private static final long LOOK_NANOS = TimeUnit.MILLISECONDS.toNanos(50);

    private SharedExchange() {
    }

    /** Runs every robot of {@code sims} (connected, in world order) until each one's simulation is over. */
    static void run(List<HardwareSimulator> sims, List<RobotControl> controls)
            throws IOException, InterruptedException {
        List<HardwareSimulator> running = new ArrayList<>();
        try {
            for (int i = 0; i < sims.size(); i++) {
                HardwareSimulator sim = sims.get(i);
                if (sim.begin(controls.get(i))) {
                    running.add(sim);
                } else {
                    sim.finish();
                }
            }
            while (!running.isEmpty()) {
                sendAll(running);
                for (int i = 0; i < running.size(); i++) {
                    HardwareSimulator sim = running.get(i);
                    if (sim == null) {
                        continue;
                    }
                    boolean more;
                    try {
                        more = sim.receive();
                    } catch (IOException e) {
                        LOG.warn("{}: {}; the other robots of this process go on", sim.name(), e.getMessage());
                        sim.endedHere("connection lost: " + e.getMessage());
                        more = false;
                    }
                    if (!more) {
                        sim.finish();
                        running.set(i, null);
                    }
                }
                running.removeIf(Objects::isNull);
            }
        } finally {
            for (HardwareSimulator sim : sims) {
                sim.finish();
            }
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(HardwareSimulator.CONTROL_GRACE_MS);
            for (HardwareSimulator sim : sims) {
                sim.awaitControlCode(TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime()));
            }
            HardwareSimulator.warnOfParameters(sims);
        }
    }

    /**
     * The shared exchange's send phase: sends each robot's request as soon as its control code has
     * blocked, those that are ready first. A control code that does not yield holds up only its own
     * robot: if, while waiting for it, a response arrives for a robot already sent, the Environment has
     * gone on without it (its step timeout dropped it), and it is finished here too.
     */
    private static void sendAll(List<HardwareSimulator> running) throws InterruptedException {
        List<HardwareSimulator> sent = new ArrayList<>(running.size());
        List<Integer> late = new ArrayList<>();
        for (int i = 0; i < running.size(); i++) {
            HardwareSimulator sim = running.get(i);
            if (sim.link().awaitControlFor(0)) {
                if (sendOrFinish(sim)) {
                    sent.add(sim);
                } else {
                    running.set(i, null);
                }
            } else {
                late.add(i);
            }
        }
        for (int i : late) {
            HardwareSimulator sim = running.get(i);
            while (!sim.link().awaitControlFor(LOOK_NANOS)) {
                if (sent.stream().anyMatch(s -> s.hasInput())) {
                    LOG.warn("{}: its control code has not yielded and the Environment went on without it; "
                            + "the other robots of this process go on", sim.name());
                    sim.endedHere("its control code did not yield in time");
                    running.set(i, null);
                    sim = null;
                    break;
                }
            }
            if (sim != null) {
                if (sendOrFinish(sim)) {
                    sent.add(sim);
                } else {
                    running.set(i, null);
                }
            }
        }
    }

    /** Sends one robot's request; on a failed connection finishes that robot alone and returns false. */
    private static boolean sendOrFinish(HardwareSimulator sim) throws InterruptedException {
        try {
            sim.send();
            return true;
        } catch (IOException e) {
            // this robot's connection failed (the Environment dropped it): only it stops
            LOG.warn("{}: {}; the other robots of this process go on", sim.name(), e.getMessage());
            sim.endedHere("connection lost: " + e.getMessage());
            return false;
        }
    }
}
