package robosim.protocol.link;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.ControlScripts;
import robosim.protocol.Printable;

/**
 * A Python script this simulator started to serve over a MessagePack link (a robot's control code, a world's loop
 * functions): {@code INTERPRETER -m MODULE SCRIPT} (the interpreter as {@link ControlScripts#interpreter} says), told
 * where its link is and the link's secret key in its environment ({@code ROBOSIM_LINK}, {@code ROBOSIM_LINK_KEY}, and
 * what else its link needs), its output logged line by line as {@code NAME: LINE} on a thread of its own, its last
 * lines kept to say why it ended; stopped, with everything it started, when its link is over.
 */
public final class ScriptProcess {
    private static final Logger LOG = LoggerFactory.getLogger(ScriptProcess.class);
    /** How long a script gets to exit after its link ended, ms; then it is stopped. */
    public static final long EXIT_GRACE_MS = 1000;
    /** How long a script that broke its link is waited for, to say its exit code, ms. */
    static final long EXIT_WAIT_MS = 5000;
    /** Lines of a script's output kept to say why it ended. */
    private static final int TAIL_LINES = 4;
    /** The longest line of a script's output logged, characters; the rest of a longer one is left out. */
    private static final int MAX_LINE = 1000;
    private static final SecureRandom KEYS = new SecureRandom();

    private final Path script;
    private final Process process;
    private final Thread reader;
    private final Deque<String> last = new ArrayDeque<>();

    private ScriptProcess(String name, Path script, Process process, Runnable atEnd) {
        this.script = script;
        this.process = process;
        reader = new Thread(() -> {
            try {
                read(name);
            } finally {
                atEnd.run();
            }
        }, "script-output[" + name + "]");
        reader.setDaemon(true);
        reader.start();
    }

    /** A new secret for a link: 32 hexadecimal digits. */
    public static String newKey() {
        byte[] b = new byte[16];
        KEYS.nextBytes(b);
        return HexFormat.of().formatHex(b);
    }

    /**
     * Starts {@code script} as {@code name}'s: {@code INTERPRETER -m module SCRIPT}, its link at {@code link} with
     * {@code key}, {@code environment} added to its environment; {@code atEnd} runs once its output ended (it exited).
     */
    public static ScriptProcess start(String name, Path script, String module, InetSocketAddress link, String key,
            Map<String, String> environment, Runnable atEnd) throws IOException {
        String interpreter = ControlScripts.interpreter();
        List<String> command = List.of(interpreter, "-m", module, script.toString());
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        builder.environment().put("ROBOSIM_LINK", link.getAddress().getHostAddress() + ":" + link.getPort());
        builder.environment().put("ROBOSIM_LINK_KEY", key);
        builder.environment().put("PYTHONUNBUFFERED", "1");
        builder.environment().putAll(environment);
        try {
            Process p = builder.start();
            LOG.debug("{}: started {} (pid {})", name, command, p.pid());
            return new ScriptProcess(name, script, p, atEnd);
        } catch (IOException e) {
            throw new IOException("cannot start " + interpreter + " for " + script + " (set "
                    + ControlScripts.INTERPRETER_VARIABLE + " to a Python 3.11+ with the robosim package: "
                    + "pip install ./python): " + e.getMessage(), e);
        }
    }

    /**
     * Why the script is gone, as {@code its script NAME exited (exit code N)HOW; its last output: ...}, or with
     * {@code what} instead of its exit when it has not exited within {@link #EXIT_WAIT_MS} (it broke its link, so it
     * is ending).
     */
    public String ended(String what, String how) throws InterruptedException {
        boolean exited = process.waitFor(EXIT_WAIT_MS, TimeUnit.MILLISECONDS);
        reader.join(EXIT_GRACE_MS);
        String tail = tail();
        return "its script " + script.getFileName() + " " + (exited ? "exited (exit code " + process.exitValue()
                + ")" : what) + how + (tail.isEmpty() ? "" : "; its last output: " + tail);
    }

    /**
     * Gives the script its grace to exit, then stops it (SIGTERM, then SIGKILL) and any process it started, and
     * awaits its output's end: within 1.75 s in all (less than the grace a robot's control code has at the end,
     * {@code HardwareSimulator.CONTROL_GRACE_MS}). The caller's interrupt, if it came, is set aside meanwhile (a
     * wait would end at once) and set again after.
     */
    public void stop() {
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
            reader.join(EXIT_GRACE_MS / 2);
        } catch (InterruptedException e) {
            interrupted = true;
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /** Logs the output line by line, each cut at {@link #MAX_LINE} characters and made safe for a log. */
    private void read(String name) {
        try (Reader r = new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8)) {
            StringBuilder line = new StringBuilder();
            boolean cut = false;
            for (int c = r.read(); c >= 0; c = r.read()) {
                if (c == '\n') {
                    said(name, line, cut);
                    line.setLength(0);
                    cut = false;
                } else if (line.length() < MAX_LINE) {
                    line.append((char) c);
                } else {
                    cut = true;
                }
            }
            if (!line.isEmpty()) {
                said(name, line, cut);
            }
        } catch (IOException ignored) {
            // (the process is gone: its output ends)
        }
    }

    private void said(String name, CharSequence line, boolean cut) {
        String shown = Printable.of(line.toString().stripTrailing()) + (cut ? "..." : "");
        LOG.info("{}: {}", name, shown);
        synchronized (last) {
            last.addLast(shown);
            if (last.size() > TAIL_LINES) {
                last.removeFirst();
            }
        }
    }

    private String tail() {
        synchronized (last) {
            return String.join(" | ", new ArrayList<>(last));
        }
    }
}
