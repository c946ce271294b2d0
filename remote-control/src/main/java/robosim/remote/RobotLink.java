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
import robosim.protocol.LineProof;
import robosim.protocol.SimulationKeys;

/**
 * The link to one {@code RemoteControlRobot}: connects (again and again, while the window is open),
 * sends command lines, and hands each reply line to a listener on its reader thread. With the
 * simulation's keys it speaks TLS when they hold the key pair and proves the shared secret before its
 * first command (see {@code RemoteControlRobot}).
 */
public final class RobotLink implements Closeable {
    private final RobotInfo robot;
    private final Consumer<String> replies;
    private final SimulationKeys keys;
    /** The TCP socket (TLS runs over it when the keys hold a key pair). */
    private volatile Socket transport;
    /** The last failure to link told to the listener, so a robot that keeps refusing is told once. */
    private volatile String lastFailure = "";
    /** An attempt to link is under way. */
    private final java.util.concurrent.atomic.AtomicBoolean connecting = new java.util.concurrent.atomic.AtomicBoolean();
    private volatile OutputStream out;
    private volatile boolean closed;

    /** @param keys the simulation's keys (null: none, the robot's link is on loopback) */
    public RobotLink(RobotInfo robot, Consumer<String> replies, SimulationKeys keys) {
        this.robot = robot;
        this.replies = replies;
        this.keys = keys;
    }

    public RobotInfo robot() {
        return robot;
    }

    public boolean connected() {
        Socket s = transport;
        return s != null && s.isConnected() && !s.isClosed();
    }

    /**
     * Tries to connect if not connected; returns whether it is. One attempt at a time: a caller that
     * comes while one is under way gets false at once (no lock is held across the network).
     */
    public boolean ensureConnected() {
        if (connected() || closed) {
            return connected();
        }
        if (!connecting.compareAndSet(false, true)) {
            return false;
        }
        try {
            return connect();
        } finally {
            connecting.set(false);
        }
    }

    private boolean connect() {
        Socket raw = new Socket();
        try {
            raw.connect(new InetSocketAddress(robot.host(), robot.port()), 1000);
        } catch (IOException e) {
            closeQuietly(raw);
            return false; // not listening (yet): the window keeps trying
        }
        // the TLS handshake and the proof must be done by the deadline, however the robot trickles its bytes
        java.util.concurrent.atomic.AtomicBoolean linked = new java.util.concurrent.atomic.AtomicBoolean();
        java.util.concurrent.CompletableFuture.delayedExecutor(LINK_DEADLINE_MS, java.util.concurrent.TimeUnit.MILLISECONDS)
                .execute(() -> {
                    if (!linked.get()) {
                        closeQuietly(raw);
                    }
                });
        try {
            raw.setTcpNoDelay(true);
            Socket s = keys == null || keys.tls() == null ? raw : keys.tls().client(raw);
            BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
            OutputStream o = s.getOutputStream();
            if (keys != null) {
                prove(in, o);
            }
            if (!linked.compareAndSet(false, true) || raw.isClosed()) {
                throw new IOException("no answer to the proof within " + LINK_DEADLINE_MS + " ms");
            }
            if (closed) { // (closed for good while linking)
                closeQuietly(raw);
                return false;
            }
            out = o;
            transport = raw;
            lastFailure = "";
            Thread reader = new Thread(() -> read(in, raw), "link[" + robot.name() + "]");
            reader.setDaemon(true);
            reader.start();
            return true;
        } catch (IOException e) {
            closeQuietly(raw);
            String failure = "error cannot link to " + robot.host() + ":" + robot.port() + ": " + e.getMessage();
            if (!failure.equals(lastFailure)) {
                lastFailure = failure;
                replies.accept(failure);
            }
            return false;
        }
    }

    /** How long the robot may take to finish TLS and answer the challenge and the proof, ms. */
    private static final int LINK_DEADLINE_MS = 20_000;

    private void prove(BufferedReader in, OutputStream o) throws IOException {
        o.write((LineProof.CHALLENGE + "\n").getBytes(StandardCharsets.UTF_8));
        o.flush();
        String challenge = in.readLine();
        if (challenge == null || !challenge.startsWith("nonce ")) {
            throw new IOException("the robot gave no challenge" + (challenge == null ? "" : ": " + abbreviate(challenge)));
        }
        o.write((LineProof.answer(keys, LineProof.REMOTE_CONTROL, challenge.substring(6).strip()) + "\n")
                .getBytes(StandardCharsets.UTF_8));
        o.flush();
        String answer = in.readLine();
        if (!"proven".equals(answer)) {
            throw new IOException("the robot refused the proof" + (answer == null ? "" : ": " + abbreviate(answer)));
        }
    }

    private static String abbreviate(String s) {
        String clean = s.replaceAll("\\p{Cntrl}", "?");
        return clean.length() > 80 ? clean.substring(0, 80) + "..." : clean;
    }

    private void read(BufferedReader in, Socket raw) {
        try (in) {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                replies.accept(line);
            }
        } catch (IOException ignored) {
            // the robot went away: connected() turns false
        } finally {
            closeQuietly(raw);
        }
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // closing
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
        Socket s = transport;
        transport = null;
        if (s != null) {
            closeQuietly(s);
        }
    }
}
