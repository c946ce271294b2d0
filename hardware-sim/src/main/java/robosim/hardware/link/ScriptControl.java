package robosim.hardware.link;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.AsynchronousCloseException;
import java.nio.channels.ClosedByInterruptException;
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
    /** Connections whose hello was refused (not the script's) before the script's own is given up on. */
    static final int MAX_STRANGERS = 8;
    /** Lines of a script's output kept to say why it ended. */
    private static final int TAIL_LINES = 4;
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
            Output output = new Output(robot.name(), process);
            process.onExit().thenRun(() -> close(server)); // (an accept waiting for a script that died ends)
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
            } catch (AsynchronousCloseException e) {
                throw new IOException(ended("exited", process, output, " before it connected"
                        + (refused == null ? "" : " (a hello refused: " + refused + ")")));
            }
            try {
                RobotLink.serve(controller.socket(), robot, key);
                return; // (its bye)
            } catch (RobotLink.HelloRefused e) {
                refused = e.getMessage();
                if (strangers >= MAX_STRANGERS) {
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

    /** Why the script is gone: its exit code (waited for a while) and its last lines of output. */
    private String ended(String what, Process process, Output output, String how) throws InterruptedException {
        boolean exited = process.waitFor(EXIT_GRACE_MS, TimeUnit.MILLISECONDS);
        output.await();
        String tail = output.tail();
        return "its script " + script.getFileName() + " " + (exited ? "exited (exit code " + process.exitValue()
                + ")" : what) + how
                + (tail.isEmpty() ? "" : "; its last output: " + tail);
    }

    /** Gives the script its grace to exit, then stops it. */
    private static void stop(Process process, Output output) throws InterruptedException {
        try {
            if (!process.waitFor(EXIT_GRACE_MS, TimeUnit.MILLISECONDS)) {
                process.destroy();
                if (!process.waitFor(EXIT_GRACE_MS, TimeUnit.MILLISECONDS)) {
                    process.destroyForcibly();
                }
            }
        } finally {
            if (!process.isAlive()) {
                output.await();
            }
        }
    }

    private static void close(ServerSocketChannel server) {
        try {
            server.close();
        } catch (IOException ignored) {
            // (closing is all)
        }
    }

    /** The script's output, logged line by line on a thread of its own, its last lines kept. */
    private static final class Output {
        private final Thread reader;
        private final Deque<String> last = new ArrayDeque<>();

        Output(String robot, Process process) {
            reader = new Thread(() -> read(robot, process), "script-output[" + robot + "]");
            reader.setDaemon(true);
            reader.start();
        }

        private void read(String robot, Process process) {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String line = r.readLine(); line != null; line = r.readLine()) {
                    String shown = Printable.of(line, 1000);
                    LOG.info("{}: {}", robot, shown);
                    synchronized (last) {
                        last.addLast(shown);
                        if (last.size() > TAIL_LINES) {
                            last.removeFirst();
                        }
                    }
                }
            } catch (IOException ignored) {
                // (the process is gone: its output ends)
            }
        }

        /** Waits a while for the output's end (the process has exited). */
        void await() throws InterruptedException {
            reader.join(EXIT_GRACE_MS);
        }

        String tail() {
            synchronized (last) {
                List<String> lines = new ArrayList<>(last);
                return String.join(" | ", lines);
            }
        }
    }
}
