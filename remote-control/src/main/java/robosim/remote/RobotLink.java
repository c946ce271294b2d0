package robosim.remote;

import java.io.BufferedReader;
import java.io.Closeable;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.function.Consumer;
import robosim.examples.RobotInfo;

/**
 * The link to one {@code RemoteControlRobot}: connects (again and again, while the window is open),
 * sends command lines, and hands each reply line to a listener on its reader thread.
 */
public final class RobotLink implements Closeable {
    private final RobotInfo robot;
    private final Consumer<String> replies;
    private volatile Socket socket;
    private volatile OutputStream out;
    private volatile boolean closed;

    public RobotLink(RobotInfo robot, Consumer<String> replies) {
        this.robot = robot;
        this.replies = replies;
    }

    public RobotInfo robot() {
        return robot;
    }

    public boolean connected() {
        Socket s = socket;
        return s != null && s.isConnected() && !s.isClosed();
    }

    /** Tries to connect if not connected; returns whether it is. */
    public synchronized boolean ensureConnected() {
        if (connected() || closed) {
            return connected();
        }
        try {
            Socket s = new Socket();
            s.connect(new InetSocketAddress(robot.host(), robot.port()), 1000);
            s.setTcpNoDelay(true);
            out = s.getOutputStream();
            socket = s;
            Thread reader = new Thread(() -> read(s), "link[" + robot.name() + "]");
            reader.setDaemon(true);
            reader.start();
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    private void read(Socket s) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                replies.accept(line);
            }
        } catch (IOException ignored) {
            // the robot went away: connected() turns false
        } finally {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing
            }
        }
    }

    /** Sends one command line; false if not connected (or the write failed). */
    public boolean send(String command) {
        if (!ensureConnected()) {
            return false;
        }
        try {
            out.write((command + "\n").getBytes(StandardCharsets.UTF_8));
            out.flush();
            return true;
        } catch (IOException e) {
            close(false);
            return false;
        }
    }

    @Override
    public void close() {
        close(true);
    }

    private void close(boolean forGood) {
        closed |= forGood;
        Socket s = socket;
        socket = null;
        if (s != null) {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing
            }
        }
    }
}
