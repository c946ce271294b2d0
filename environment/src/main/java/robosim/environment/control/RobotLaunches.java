package robosim.environment.control;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Environment's robot launcher ({@code --launch-robots}, as {@code headless.sh} starts it): the control
 * port's {@code add ... CONTROL} starts that robot's process here, {@code robosim.hardware.RobotMain} on this
 * JVM's class path, connecting to this Environment's robot port (on the address it listens on; loopback when
 * it listens on every address), with this process's environment (its keys). Its output goes to this log,
 * each line prefixed with the robot's name (thread {@code robot-output[name]}, which blocks in its read); when the
 * Environment closes, each still running gets a grace period to exit and is then stopped. At most
 * {@link #MAX} at once.
 */
public final class RobotLaunches implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(RobotLaunches.class);
    /** Robot processes this Environment runs at once, at most. */
    public static final int MAX = 64;
    private static final Pattern CLASS_NAME = Pattern.compile("[A-Za-z_$][\\w$]*(\\.[A-Za-z_$][\\w$]*)*");

    /** How long closing waits for the robot processes (told the end already) to exit by themselves, ms. */
    private static final long GRACE_MS = 10_000;

    private final List<Process> running = new ArrayList<>();
    private final List<Thread> outputs = new ArrayList<>();

    /**
     * Null if a robot process with this control class may start now, else why not: a bad class name, a class
     * the robot process would not find (it runs on this JVM's class path) or that is no control class, too many
     * processes. The class is looked up, never initialised.
     */
    public synchronized String check(String control) {
        running.removeIf(p -> !p.isAlive());
        String missing = controlClassProblem(control, "its robot process would run with");
        if (missing != null) {
            return missing;
        }
        return running.size() >= MAX ? "this Environment runs " + MAX + " robot processes already" : null;
    }

    /**
     * Why {@code control} could not be a control class on this JVM's class path (as
     * {@link robosim.protocol.ControlClasses} finds it), or null; {@code whose} says whose class path that
     * is ("its robot process would run with"). The class is looked up, never initialised.
     */
    public static String controlClassProblem(String control, String whose) {
        if (robosim.protocol.ControlScripts.isScript(control)) {
            return robosim.protocol.ControlScripts.problem(control);
        }
        if (robosim.protocol.ControlScripts.isRos2(control)) {
            return robosim.protocol.ControlScripts.ros2Elsewhere();
        }
        if (!CLASS_NAME.matcher(control).matches() || control.length() > 200) {
            return "\"" + ControlReplies.abbreviate(control, 64) + "\" is not a Java class name";
        }
        ClassLoader loader = robosim.protocol.ControlClasses.loader();
        Class<?> c;
        try {
            c = Class.forName(control, false, loader);
        } catch (ClassNotFoundException | LinkageError e) {
            return "there is no class " + control + " on the class path " + whose + " (a class of your own: "
                    + "--classpath or ROBOSIM_CLASSPATH)";
        }
        try {
            Class<?> api = Class.forName("robosim.api.RobotControl", false, loader);
            return api.isAssignableFrom(c) ? null : control + " is not a RobotControl";
        } catch (ClassNotFoundException e) {
            return null; // (no robot API here to check against: the robot process says)
        }
    }

    /**
     * Starts robot {@code name}'s process, connecting to {@code host}'s robot port; a refusal ({@link #check}) or
     * a process that cannot start is an IOException saying why.
     */
    public synchronized void start(String name, String type, String control, String host, int robotPort)
            throws IOException {
        String refusal = check(control);
        if (refusal != null) {
            throw new IOException(refusal);
        }
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-Dio.netty.noUnsafe=true", "-Dmsgpack.universal-buffer=true"));
        cmd.addAll(robosim.protocol.LogLevel.jvmOptions());
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "robosim.hardware.RobotMain", control, name,
                host, Integer.toString(robotPort), "--type", type));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        running.add(p);
        Thread out = new Thread(() -> pipe(name, p), "robot-output[" + name + "]");
        out.setDaemon(true);
        out.start();
        outputs.add(out);
        LOG.info("started robot {}'s process ({}, pid {})", name, control, p.pid());
    }

    private static void pipe(String name, Process p) {
        try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                LOG.info("robot {}: {}", name, line.replaceAll("\\p{Cntrl}", "?"));
            }
        } catch (IOException e) {
            // the process is gone
        }
        try {
            LOG.info("robot {}'s process exited ({})", name, p.waitFor());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * The Environment is closing: each robot process still running (it has been told the end) gets up to
     * {@link #GRACE_MS} in all to exit and its output to reach the log; one still running then is stopped.
     */
    @Override
    public void close() {
        List<Process> processes;
        List<Thread> pipes;
        synchronized (this) {
            processes = List.copyOf(running);
            pipes = List.copyOf(outputs);
            running.clear();
            outputs.clear();
        }
        long deadline = System.nanoTime() + GRACE_MS * 1_000_000;
        try {
            for (Process p : processes) {
                if (!p.waitFor(Math.max(0, deadline - System.nanoTime()), java.util.concurrent.TimeUnit.NANOSECONDS)) {
                    LOG.warn("a robot process (pid {}) did not exit within {} ms of the end; stopping it", p.pid(),
                            GRACE_MS);
                    p.destroy();
                }
            }
            for (Thread t : pipes) {
                t.join(Math.max(1, (deadline - System.nanoTime()) / 1_000_000));
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            processes.forEach(Process::destroy);
        }
    }
}
