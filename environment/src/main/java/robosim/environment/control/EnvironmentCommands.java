package robosim.environment.control;

import static robosim.environment.control.ControlReplies.error;
import static robosim.environment.control.ControlReplies.ok;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.TimeUnit;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.environment.net.RobotState;
import robosim.environment.net.RunStatus;

/**
 * The Environment's control requests: {@code status}, {@code start}, {@code stop}, {@code pause},
 * {@code resume}, {@code step N}, {@code load FILE} (only under the {@link EnvironmentDirectories}),
 * {@code shutdown}, {@code robots} (each robot's {@link RobotState}) and {@code remove NAME}, on the
 * {@link EnvironmentHost}'s current simulation.
 */
public final class EnvironmentCommands implements ControlCommands {
    /** How long a waiting request (step N, pause) may take before it answers anyway, s. */
    private static final long WAIT_S = 600;

    private final EnvironmentHost host;
    private final EnvironmentDirectories directories;

    public EnvironmentCommands(EnvironmentHost host, EnvironmentDirectories directories) {
        this.host = host;
        this.directories = directories;
    }

    @Override
    public boolean waits(String verb) {
        return verb.equals("step") || verb.equals("pause") || verb.equals("start") || verb.equals("load")
                || verb.equals("remove");
    }

    @Override
    public String known() {
        return "status, start, stop, pause, resume, step N, load FILE, shutdown, robots, remove NAME";
    }

    @Override
    public ObjectNode handle(String verb, String arg) throws Exception {
        return switch (verb) {
            case "status" -> status();
            case "start" -> ok(host.start());
            case "resume" -> {
                host.current().resume();
                yield ok("running");
            }
            case "pause" -> {
                host.current().pause(WAIT_S, TimeUnit.SECONDS);
                yield ok("paused at step " + host.current().status().step());
            }
            case "step" -> {
                long at = host.current().step(ControlReplies.positive("step", arg), WAIT_S, TimeUnit.SECONDS);
                yield ok("paused at step " + at);
            }
            case "stop" -> ok(host.stop());
            case "load" -> arg.isEmpty() ? error("load needs a file: load FILE") : ok(host.load(directories.resolve(arg)));
            case "shutdown" -> ok(host.shutdown());
            case "robots" -> {
                ObjectNode n = ok(null);
                n.putPOJO("robots", states(host.current().status()));
                yield n;
            }
            case "remove" -> {
                if (arg.isEmpty()) {
                    yield error("remove needs a robot's name: remove NAME");
                }
                String why = host.current().remove(arg);
                yield why == null ? ok("removed " + ControlReplies.abbreviate(arg)) : error(why);
            }
            default -> null;
        };
    }

    /** Each robot as {"name", "state", "since"} ("since": the step it is held, waited for or gone since). */
    private static List<Map<String, Object>> states(RunStatus s) {
        List<Map<String, Object>> l = new ArrayList<>();
        for (RobotState r : s.states()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("name", r.name());
            m.put("state", r.state());
            if (r.sinceStep() >= 0) {
                m.put("since", r.sinceStep());
            }
            l.add(m);
        }
        return l;
    }

    private ObjectNode status() {
        RunStatus s = host.current().status();
        ObjectNode n = ok(null);
        n.put("state", s.state().name());
        n.put("step", s.step());
        n.put("steps_per_s", Math.round(s.stepsPerSecond() * 10) / 10.0);
        n.put("file", String.valueOf(host.file()));
        n.putPOJO("robots", s.robots());
        n.putPOJO("connected", s.connected());
        n.putPOJO("left", s.left());
        n.putPOJO("robot_states", states(s));
        n.put("geometry", s.geometry());
        n.put("viewers", s.viewers());
        if (!s.reason().isEmpty()) {
            n.put("reason", s.reason());
        }
        return n;
    }
}
