package robosim.testkit;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.protocol.CommEvent;
import robosim.protocol.InMemoryLink;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.Report;
import robosim.protocol.SensorReading;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * One robot of a {@link Simulation} as the test sees it: its Hardware Simulator's end of the in-memory link,
 * with what the Environment told it kept on the way (its pose, its last readings, and, unless told to keep no history,
 * every message and contact) and what it reported in its requests (the newest value of each name; a request goes out from the loop's
 * thread or, through {@link #environment}, from its control thread). Those threads write; the test reads once a
 * step it asked for is out (the loop's answer orders the two), under this object's lock all the same.
 */
final class WatchedRobot implements InMemoryLink.Robot {
    private InMemoryLink.Robot robot;
    private final String name;
    private final Map<String, Double> reports = new LinkedHashMap<>();
    private Pose pose;
    private StepResponse last;
    private final List<Received> received = new ArrayList<>();
    private final List<Contact> contacts = new ArrayList<>();
    private String end;
    /** Whether it keeps every message and contact ({@link Simulation.Builder#history}). */
    private final boolean history;

    WatchedRobot(String name, boolean history) {
        this.name = name;
        this.history = history;
    }

    /** Its Hardware Simulator's end, once started (before the Environment uses this robot). */
    void attach(InMemoryLink.Robot started) {
        robot = started;
    }

    /** {@code environment}, seeing the requests the robot's control thread sends it. */
    InMemoryLink.Environment environment(InMemoryLink.Environment environment) {
        return request -> {
            requested(request);
            environment.request(request);
        };
    }

    private StepRequest requested(StepRequest request) {
        if (request != null && !request.reports().isEmpty()) {
            synchronized (this) {
                for (Report r : request.reports()) {
                    reports.put(r.name(), r.value());
                }
            }
        }
        return request;
    }

    @Override
    public RobotHello hello() {
        return robot.hello();
    }

    @Override
    public void welcome(RobotWelcome welcome) {
        synchronized (this) {
            if (welcome.isAccepted()) {
                pose = new Pose(welcome.xMm(), welcome.yMm(), welcome.headingDeg());
            }
        }
        robot.welcome(welcome);
    }

    @Override
    public StepRequest step(long k) {
        return requested(robot.step(k));
    }

    @Override
    public StepRequest respond(StepResponse response, long next) {
        synchronized (this) {
            last = response;
            pose = new Pose(response.xMm(), response.yMm(), response.headingDeg());
            for (int i = 0; history && i < response.inbox().size(); i++) {
                CommEvent m = response.inbox().get(i);
                received.add(new Received(response.step(), m.from(), m.payload()));
            }
            if (history && response.contact() != null && !response.contact().isEmpty()) {
                contacts.add(new Contact(response.step(), response.contact()));
            }
        }
        return requested(robot.respond(response, next));
    }

    @Override
    public void end(SimulationEnd end) {
        synchronized (this) {
            this.end = end.reason();
        }
        robot.end(end);
    }

    String name() {
        return name;
    }

    synchronized Pose pose() {
        return pose;
    }

    /** The sonar ranges of its last step, mm (empty before step 0 or for a robot without sonar). */
    synchronized double[] sonar() {
        return last == null || last.sonarMm() == null ? new double[0] : last.sonarMm().clone();
    }

    /** Sensor {@code sensor}'s values in its last step, or null if it gave none. */
    synchronized double[] reading(String sensor) {
        if (last != null && last.readings() != null) {
            for (SensorReading r : last.readings()) {
                if (r.name().equals(sensor)) {
                    return r.values().clone();
                }
            }
        }
        return null;
    }

    synchronized List<Received> received() {
        kept("messages");
        return List.copyOf(received);
    }

    synchronized List<Contact> contacts() {
        kept("contacts");
        return List.copyOf(contacts);
    }

    private void kept(String what) {
        if (!history) {
            throw new IllegalStateException("robot " + name + "'s " + what + " are not kept: the simulation was "
                    + "started to keep no history");
        }
    }

    /** The newest value of each name it reported, in the order first reported. */
    synchronized Map<String, Double> reports() {
        return new LinkedHashMap<>(reports);
    }

    /** Why the simulation ended for it, or null while it takes part. */
    synchronized String end() {
        return end;
    }
}
