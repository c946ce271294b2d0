package robosim.environment.control;

import static robosim.environment.control.ControlReplies.error;
import static robosim.environment.control.ControlReplies.ok;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.TimeUnit;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.RobotState;
import robosim.environment.run.RunStatus;

/**
 * The Environment's control requests, on the {@link EnvironmentHost}'s current simulation: each declared once, in
 * {@link #verbs}, with the thread that answers it, its help and its handler ({@code load} reads only under the
 * {@link EnvironmentDirectories}).
 */
public final class EnvironmentCommands implements ControlCommands {
    /** How long a waiting request (step N, pause) may take before it answers anyway, s. */
    private static final long WAIT_S = 600;

    private final EnvironmentHost host;
    private final EnvironmentDirectories directories;
    private final List<ControlVerb> verbs;

    public EnvironmentCommands(EnvironmentHost host, EnvironmentDirectories directories) {
        this.host = host;
        this.directories = directories;
        this.verbs = List.of(
                ControlVerb.quick("status", "the run's state, step, rate, robots, Geometry and viewers",
                        arg -> status()),
                ControlVerb.waiting("start", "resumes, or after the end runs the same file again", arg -> ok(host.start())),
                ControlVerb.quick("stop", "ends the simulation (every client is told)", arg -> ok(host.stop())),
                ControlVerb.waiting("pause", "holds the run after the step in progress", arg -> {
                    host.current().pause(WAIT_S, TimeUnit.SECONDS);
                    return ok("paused at step " + host.current().status().step());
                }),
                ControlVerb.quick("resume", "runs on", arg -> {
                    host.current().resume();
                    return ok("running");
                }),
                ControlVerb.waiting("step N", "runs N more steps and holds again", arg -> ok("paused at step "
                        + host.current().step(ControlReplies.positive("step", arg), WAIT_S, TimeUnit.SECONDS))),
                ControlVerb.waiting("load FILE", "ends the simulation and waits for FILE's robots", arg -> arg.isEmpty()
                        ? error("load needs a file: load FILE") : ok(host.load(directories.resolve(arg)))),
                ControlVerb.quick("shutdown", "ends the simulation and the Environment", arg -> ok(host.shutdown())),
                ControlVerb.quick("robots", "each robot and its state", arg -> {
                    ObjectNode n = ok(null);
                    n.putPOJO("robots", states(host.current().status()));
                    return n;
                }),
                ControlVerb.waiting("add NAME TYPE X Y HEADING [CONTROL]", "a robot joins the running world at X, Y m",
                        this::add),
                ControlVerb.waiting("remove NAME", "takes a robot out of the run for good", arg -> {
                    if (arg.isEmpty()) {
                        return error("remove needs a robot's name: remove NAME");
                    }
                    String why = host.current().roster().remove(arg);
                    return why == null ? ok("removed " + ControlReplies.abbreviate(arg)) : error(why);
                }));
    }

    @Override
    public List<ControlVerb> verbs() {
        return verbs;
    }

    /** {@code add NAME TYPE X Y HEADING [CONTROL]}: metres and degrees; CONTROL starts its process with a launcher. */
    private ObjectNode add(String arg) throws Exception {
        String[] w = arg.isEmpty() ? new String[0] : arg.split("\\s+");
        if (w.length < 5 || w.length > 6) {
            return error("add needs NAME TYPE X Y HEADING [CONTROL] (metres, degrees), got " + w.length + " value(s)");
        }
        double[] pose = new double[3];
        for (int k = 0; k < 3; k++) {
            try {
                pose[k] = Double.parseDouble(w[2 + k]);
            } catch (NumberFormatException e) {
                return error("add: " + new String[] {"X", "Y", "HEADING"}[k] + " must be a number, got \""
                        + ControlReplies.abbreviate(w[2 + k]) + "\"");
            }
        }
        String control = w.length == 6 ? w[5] : "";
        ClientWorkerCoordinator current = host.current();
        boolean here = !control.isEmpty() && current.runsRobotsInThisJvm(); // (--one-jvm: it starts in this JVM)
        String cannot = here ? RobotLaunches.controlClassProblem(control, "this Environment runs with")
                : control.isEmpty() || host.launches() == null ? null : host.launches().check(control);
        if (cannot != null) {
            return error("add " + ControlReplies.abbreviate(w[0]) + ": " + cannot);
        }
        String why = current.roster().add(w[0], w[1], pose[0], pose[1], pose[2], control);
        if (why != null) {
            return error("add " + ControlReplies.abbreviate(w[0]) + ": " + why);
        }
        if (here) {
            String failed = current.roster().startHere(w[0], w[1], control);
            if (failed != null) {
                current.roster().remove(w[0]); // (not let in: nothing will say hello as it)
                return error("add " + w[0] + ": it could not start in this JVM: " + failed);
            }
            return ok("added " + w[0] + " and started it in this JVM (" + control + ")");
        }
        if (control.isEmpty() || host.launches() == null) {
            return ok("added " + w[0] + ": it joins when a robot process says hello as " + w[0]
                    + (control.isEmpty() ? "" : " (this Environment starts no robot processes: no --launch-robots)"));
        }
        try {
            host.launches().start(w[0], w[1], control, host.robotHost(), host.ports()[0]);
        } catch (java.io.IOException e) {
            host.current().roster().remove(w[0]); // (not let in: nothing will say hello as it)
            return error("add " + w[0] + ": its robot process could not start: " + e.getMessage());
        }
        return ok("added " + w[0] + " and started its robot process (" + control + ")");
    }

    /** Each robot as {"name", "state", "since"} ("since": the step it is held, waited for or gone since). */
    private static List<Map<String, Object>> states(RunStatus s) {
        List<Map<String, Object>> l = new ArrayList<>();
        for (RobotState r : s.states()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("name", r.name());
            m.put("state", r.state());
            if (r.sinceStep() >= 0) {
                m.put("since", robosim.protocol.StepNumbers.shown(r.sinceStep()));
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
