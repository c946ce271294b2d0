package robosim.hardware.link;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ClosedByInterruptException;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.file.Path;
import java.util.Map;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.Robot;
import robosim.api.RobotControl;
import robosim.protocol.ControlScripts;
import robosim.protocol.link.LinkHello;
import robosim.protocol.link.ScriptProcess;

/**
 * Control code that is a Python script ({@code control="python:wander.py"}): run as its robot's control code, it
 * starts {@code INTERPRETER -m robosim SCRIPT} (the package in {@code python/}; the interpreter as
 * {@link ControlScripts#interpreter} says) with the robot link's address, the robot's name and a secret key in its
 * environment ({@code ROBOSIM_LINK}, {@code ROBOSIM_ROBOT}, {@code ROBOSIM_LINK_KEY}), and serves the robot to it
 * over the link ({@link RobotLink}) on a loopback port the system picks. Its output is logged line by line,
 * {@code NAME: LINE}. Its bye ends the control code as a return does; its reported failure (a traceback) as a throw;
 * a script that exits or stops answering without either is control code that failed, saying its exit code and its
 * last line of output. The end of the simulation ends the link ({@code over}): the script's calls raise, it exits,
 * and a script that has not within {@link ScriptProcess#EXIT_GRACE_MS} is stopped ({@link ScriptProcess}).
 */
public final class ScriptControl implements RobotControl {
    private static final Logger LOG = LoggerFactory.getLogger(ScriptControl.class);
    /** Connections whose hello was refused (not the script's) before the script's own is given up on. */
    static final int MAX_STRANGERS = 8;

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
        String key = ScriptProcess.newKey();
        try (ServerSocketChannel server = ServerSocketChannel.open()) {
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 1);
            InetSocketAddress at = (InetSocketAddress) server.getLocalAddress();
            // (its output's end, the script's exit, closes the channel: an accept waiting for a script that died ends)
            ScriptProcess process = ScriptProcess.start(robot.name(), script, "robosim", at, key,
                    Map.of("ROBOSIM_ROBOT", robot.name()), () -> close(server));
            try {
                serve(robot, server, process, key);
            } finally {
                process.stop();
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

    /** Takes the script's connection (strangers refused) and serves the robot to it until the link ends. */
    private void serve(Robot robot, ServerSocketChannel server, ScriptProcess process, String key)
            throws IOException, InterruptedException {
        String refused = null;
        for (int strangers = 0;; strangers++) {
            SocketChannel controller;
            try {
                controller = server.accept();
            } catch (ClosedByInterruptException e) {
                throw e;
            } catch (ClosedChannelException e) { // (closed by the script's end, before or during the accept)
                throw new IOException(process.ended("exited", " before it connected"
                        + (refused == null ? "" : " (a hello refused: " + refused + ")")));
            }
            try {
                RobotLink.serve(controller.socket(), robot, key);
                return; // (its bye)
            } catch (LinkHello.HelloRefused e) {
                refused = e.getMessage();
                if (strangers + 1 >= MAX_STRANGERS) {
                    throw new IOException(process.ended("was not heard", ": " + MAX_STRANGERS
                            + " hellos refused, the last: " + refused));
                }
                LOG.warn("{}: a hello on its robot link refused: {}", robot.name(), refused);
            } catch (RobotLink.ControllerFailure e) {
                throw e;
            } catch (IOException e) {
                if (Thread.currentThread().isInterrupted()) {
                    throw e;
                }
                throw new IOException(process.ended("ended the link", ": " + e.getMessage()), e);
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
}
