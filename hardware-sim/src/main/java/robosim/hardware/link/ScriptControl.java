package robosim.hardware.link;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ClosedByInterruptException;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.Robot;
import robosim.api.RobotControl;
import robosim.protocol.ControlScripts;
import robosim.protocol.Printable;

/**
 * Control code that is a Python script ({@code control="python:wander.py"}): run as its robot's control code, it
 * starts {@code INTERPRETER -m robosim SCRIPT} (the package in {@code python/}; the interpreter as
 * {@link ControlScripts#interpreter} says) with the robot link's address, the robot's name and a secret key in its
 * environment ({@code ROBOSIM_LINK}, {@code ROBOSIM_ROBOT}, {@code ROBOSIM_LINK_KEY}), and serves the robot to it
 * over the link ({@link RobotLink}) on a loopback port the system picks. Its output is logged line by line,
 * {@code NAME: LINE}. Its bye ends the control code as a return does; its reported failure (a traceback) as a throw;
 * a script that exits or stops answering without either is control code that failed, saying its exit code and its
 * last line of output. The end of the simulation ends the link ({@code over}): the script's calls raise, it exits,
 * and a script that has not within {@link #EXIT_GRACE_MS} is stopped.
 */
public final class ScriptControl implements RobotControl {
    private static final Logger LOG = LoggerFactory.getLogger(ScriptControl.class);
    /** How long a script gets to exit after its link ended, ms; then it is stopped. */
    static final long EXIT_GRACE_MS = 1000;
    /** How long a script that broke its link is waited for, to say its exit code, ms. */
    static final long EXIT_WAIT_MS = 5000;
    /** Connections whose hello was refused (not the script's) before the script's own is given up on. */
    static final int MAX_STRANGERS = 8;
    /** Lines of a script's output kept to say why it ended. */
    private static final int TAIL_LINES = 4;
    /** The longest line of a script's output logged, characters; the rest of a longer one is left out. */
    private static final int MAX_LINE = 1000;
    private static final SecureRandom KEYS = new SecureRandom();

    private final String control;
    private final Path script;

    /** The script {@code control} names ({@code python:PATH}, {@link ControlScripts}); checked when it runs. */
    public ScriptControl(String control) {
        this.control = control;
        this.script = ControlScripts.script(control);
    }

    @Override
    public void run(Robot robot) throws InterruptedException {
        String problem = ControlScripts.problem(control);
        if (problem != null) {
            throw new IllegalArgumentException(problem);
        }
        String key = HexFormat.of().formatHex(randomBytes());
        try (ServerSocketChannel server = ServerSocketChannel.open()) {
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 1);
            InetSocketAddress at = (InetSocketAddress) server.getLocalAddress();
            Process process = start(robot.name(), at, key);
            // (its output's end, the script's exit, closes the channel: an accept waiting for a script that died ends)
            Output output = new Output(robot.name(), process, () -> close(server));
            try {
                serve(robot, server, process, output, key);
            } finally {
                stop(process, output);
            }
        } catch (ClosedByInterruptException e) {
            throw new InterruptedException("the simulation is over");
        } catch (IOException e) {
            if (Thread.currentThread().isInterrupted()) {
                throw new InterruptedException("the simulation is over");
            }
            throw new ScriptFailure(e.getMessage());
        }
    }

    /** A script that could not be started, or ended without a bye or a failure of its own; says why, in its message. */
    public static final class ScriptFailure extends RuntimeException {
        private static final long serialVersionUID = 1L;

        ScriptFailure(String why) {
            super(why, null, false, false);
        }

        /** Its message alone (the why is all: a Java stack would say nothing of the script). */
        @Override
        public String toString() {
            return getMessage();
        }
    }

    private static byte[] randomBytes() {
        byte[] b = new byte[16];
        KEYS.nextBytes(b);
        return b;
    }

    private Process start(String name, InetSocketAddress at, String key) throws IOException {
        String interpreter = ControlScripts.interpreter();
        List<String> command = List.of(interpreter, "-m", "robosim", script.toString());
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        builder.environment().put("ROBOSIM_LINK", at.getAddress().getHostAddress() + ":" + at.getPort());
        builder.environment().put("ROBOSIM_ROBOT", name);
        builder.environment().put("ROBOSIM_LINK_KEY", key);
        builder.environment().put("PYTHONUNBUFFERED", "1");
        try {
            Process p = builder.start();
            LOG.debug("{}: started {} (pid {})", name, command, p.pid());
            return p;
        } catch (IOException e) {
            throw new IOException("cannot start " + interpreter + " for " + script + " (set "
                    + ControlScripts.INTERPRETER_VARIABLE + " to a Python 3.11+ with the robosim package: "
                    + "pip install ./python): " + e.getMessage(), e);
        }
    }

    /** Takes the script's connection (strangers refused) and serves the robot to it until the link ends. */
    private void serve(Robot robot, ServerSocketChannel server, Process process, Output output, String key)
            throws IOException, InterruptedException {
        String refused = null;
        for (int strangers = 0;; strangers++) {
            SocketChannel controller;
            try {
                controller = server.accept();
            } catch (ClosedByInterruptException e) {
                throw e;
            } catch (ClosedChannelException e) { // (closed by the script's end, before or during the accept)
                throw new IOException(ended("exited", process, output, " before it connected"
                        + (refused == null ? "" : " (a hello refused: " + refused + ")")));
            }
            try {
                RobotLink.serve(controller.socket(), robot, key);
                return; // (its bye)
            } catch (LinkHello.HelloRefused e) {
                refused = e.getMessage();
                if (strangers + 1 >= MAX_STRANGERS) {
                    throw new IOException(ended("was not heard", process, output, ": " + MAX_STRANGERS
                            + " hellos refused, the last: " + refused));
                }
                LOG.warn("{}: a hello on its robot link refused: {}", robot.name(), refused);
            } catch (RobotLink.ControllerFailure e) {
                throw e;
            } catch (IOException e) {
                if (Thread.currentThread().isInterrupted()) {
                    throw e;
                }
                throw new IOException(ended("ended the link", process, output, ": " + e.getMessage()), e);
            }
        }
    }

    /**
     * Why the script is gone: its exit code (waited for up to {@link #EXIT_WAIT_MS}: it broke its link, so it is
     * ending) and its last lines of output.
     */
    private String ended(String what, Process process, Output output, String how) throws InterruptedException {
        boolean exited = process.waitFor(EXIT_WAIT_MS, TimeUnit.MILLISECONDS);
        output.await(EXIT_GRACE_MS);
        String tail = output.tail();
        return "its script " + script.getFileName() + " " + (exited ? "exited (exit code " + process.exitValue()
                + ")" : what) + how
                + (tail.isEmpty() ? "" : "; its last output: " + tail);
    }

    /**
     * Gives the script its grace to exit, then stops it (SIGTERM, then SIGKILL) and any process it started, and
     * awaits its output's end: within 1.75 s in all, less than the grace a robot's control code has at the end
     * ({@code HardwareSimulator.CONTROL_GRACE_MS}). The end's interrupt,
     * if it came, is set aside meanwhile (a wait would end at once) and set again after.
     */
    private static void stop(Process process, Output output) {
        boolean interrupted = Thread.interrupted();
        List<ProcessHandle> descendants = process.descendants().toList(); // (its own children: stopped with it)
        try {
            if (!process.waitFor(EXIT_GRACE_MS, TimeUnit.MILLISECONDS)) {
                process.destroy();
                process.waitFor(EXIT_GRACE_MS / 4, TimeUnit.MILLISECONDS);
            }
        } catch (InterruptedException e) {
            interrupted = true;
        } finally {
            if (process.isAlive()) {
                process.destroyForcibly();
            }
            descendants.forEach(ProcessHandle::destroyForcibly);
        }
        try {
            output.await(EXIT_GRACE_MS / 2);
        } catch (InterruptedException e) {
            interrupted = true;
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    private static void close(ServerSocketChannel server) {
        try {
            server.close();
        } catch (IOException ignored) {
            // (closing is all)
        }
    }

    /**
     * The script's output, logged line by line (each cut at {@link #MAX_LINE} characters and made safe for a log) on
     * a thread of its own, its last lines kept; its end (the script's exit) runs {@code atEnd}.
     */
    private static final class Output {
        private final Thread reader;
        private final Deque<String> last = new ArrayDeque<>();

        Output(String robot, Process process, Runnable atEnd) {
            reader = new Thread(() -> {
                try {
                    read(robot, process);
                } finally {
                    atEnd.run();
                }
            }, "script-output[" + robot + "]");
            reader.setDaemon(true);
            reader.start();
        }

        private void read(String robot, Process process) {
            try (Reader r = new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8)) {
                StringBuilder line = new StringBuilder();
                boolean cut = false;
                for (int c = r.read(); c >= 0; c = r.read()) {
                    if (c == '\n') {
                        said(robot, line, cut);
                        line.setLength(0);
                        cut = false;
                    } else if (line.length() < MAX_LINE) {
                        line.append((char) c);
                    } else {
                        cut = true;
                    }
                }
                if (!line.isEmpty()) {
                    said(robot, line, cut);
                }
            } catch (IOException ignored) {
                // (the process is gone: its output ends)
            }
        }

        private void said(String robot, CharSequence line, boolean cut) {
            String shown = Printable.of(line.toString().stripTrailing()) + (cut ? "..." : "");
            LOG.info("{}: {}", robot, shown);
            synchronized (last) {
                last.addLast(shown);
                if (last.size() > TAIL_LINES) {
                    last.removeFirst();
                }
            }
        }

        /** Waits up to {@code ms} for the output's end (the process has exited). */
        void await(long ms) throws InterruptedException {
            reader.join(ms);
        }

        String tail() {
            synchronized (last) {
                return String.join(" | ", new ArrayList<>(last));
            }
        }
    }
}
