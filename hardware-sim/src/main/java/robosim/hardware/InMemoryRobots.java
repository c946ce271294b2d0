package robosim.hardware;

import robosim.devices.RobotType;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.TimeUnit;
import robosim.api.RobotControl;
import robosim.protocol.InMemoryLink;

/**
 * The Hardware Simulator's robots for a one-JVM run, found by the Environment through
 * {@code META-INF/services/robosim.protocol.InMemoryLink$Starter}: each an {@link InMemoryRobot} with its
 * type and a new instance of its control class, found on this JVM's class path; or, for a caller that
 * holds the control object itself (the testkit), that object.
 */
public final class InMemoryRobots implements InMemoryLink.Starter {
    /** Every robot this starter started, for the wait at the end. */
    private final List<InMemoryRobot> started = Collections.synchronizedList(new ArrayList<>());

    @Override
    public InMemoryLink.Robot start(String name, String type, String controlClass,
            InMemoryLink.Environment environment) {
        return start(name, type, RobotLauncher.control(controlClass), environment);
    }

    @Override
    public InMemoryLink.ControlEnd awaitControlCode(long ms) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ms);
        List<InMemoryRobot> all;
        synchronized (started) {
            all = new ArrayList<>(started);
        }
        List<String> failed = new ArrayList<>();
        List<String> running = new ArrayList<>();
        java.util.Map<String, java.util.Set<String>> asked = new java.util.LinkedHashMap<>();
        for (InMemoryRobot r : all) {
            asked.put(r.name(), r.parameterAsks().asked());
            if (!r.awaitControlCode(Math.max(0, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())))) {
                running.add(r.name());
            }
            String why = r.controlFailure();
            if (why != null) {
                failed.add(why);
            }
        }
        return new InMemoryLink.ControlEnd(failed, running, asked);
    }

    /** What the control code of each robot this starter started threw out of {@code run} so far, in start order. */
    public List<ControlFailure> failures() {
        List<ControlFailure> failures = new ArrayList<>();
        synchronized (started) {
            for (InMemoryRobot r : started) {
                ControlFailure f = r.failure();
                if (f != null) {
                    failures.add(f);
                }
            }
        }
        return failures;
    }

    /**
     * A robot named {@code name} of {@code type} ({@code ArRobot}, {@code Scout} or a RobotType class) running
     * {@code control}, an object of the caller's (the testkit), whose requests go to {@code environment}.
     *
     * @throws IllegalArgumentException naming an unknown type
     */
    public InMemoryLink.Robot start(String name, String type, RobotControl control,
            InMemoryLink.Environment environment) {
        InMemoryRobot r = new InMemoryRobot(new HardwareSimulator(name, robosim.devices.RobotTypes.byName(type)), control, environment);
        started.add(r);
        return r;
    }
}
