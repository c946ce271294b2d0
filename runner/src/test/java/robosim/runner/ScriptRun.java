package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * One run of a script in a session of its own (setsid), waited for; every process the script started
 * must have ended with it (processes that still end within a few seconds are waited for).
 */
record ScriptRun(int exit, String stdout, String stderr) {
    private static final long RUN_SECONDS = 90;
    private static final long LINGER_SECONDS = 15;

    /** Runs {@code cmd} in {@code dir} with {@code env} added (and no ROBOSIM_* of ours); logs go to {@code logs}. */
    static ScriptRun of(Path dir, Map<String, String> env, Path logs, String... cmd) throws Exception {
        return within(RUN_SECONDS, dir, env, logs, cmd);
    }

    /** As {@link #of}, for a script that may take up to {@code seconds}. */
    static ScriptRun within(long seconds, Path dir, Map<String, String> env, Path logs, String... cmd) throws Exception {
        Path out = Files.createTempFile(logs, "stdout", ".txt");
        Path err = Files.createTempFile(logs, "stderr", ".txt");
        Process p = start(dir, env, cmd, ProcessBuilder.Redirect.to(out.toFile()), err);
        int exit = awaitWithEveryProcess(p, cmd, seconds);
        return new ScriptRun(exit, Files.readString(out), Files.readString(err));
    }

    /** As {@link #of}, but stops the script (SIGTERM) as soon as it prints a line starting with {@code line}. */
    static ScriptRun terminatedAfter(String line, Path dir, Map<String, String> env, Path logs, String... cmd)
            throws Exception {
        Path err = Files.createTempFile(logs, "stderr", ".txt");
        Process p = start(dir, env, cmd, ProcessBuilder.Redirect.PIPE, err);
        StringBuilder seen = new StringBuilder();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String l = r.readLine();
            while (l != null && !l.startsWith(line)) {
                seen.append(l).append('\n');
                l = r.readLine();
            }
            assertTrue(l != null, String.join(" ", cmd) + " ended before printing '" + line + "': " + seen);
            p.destroy();
            int exit = awaitWithEveryProcess(p, cmd, RUN_SECONDS);
            return new ScriptRun(exit, seen.toString(), Files.readString(err));
        } finally {
            p.destroyForcibly();
        }
    }

    private static Process start(Path dir, Map<String, String> env, String[] cmd, ProcessBuilder.Redirect stdout,
            Path stderr) throws IOException {
        List<String> full = new ArrayList<>(List.of("setsid"));
        full.addAll(List.of(cmd));
        ProcessBuilder pb = new ProcessBuilder(full).directory(dir.toFile()).redirectOutput(stdout)
                .redirectError(stderr.toFile());
        // (the user's settings are not the test's; the build's ROBOSIM_CDS, runner/pom.xml, is kept)
        pb.environment().keySet().removeIf(k -> k.startsWith("ROBOSIM_") && !k.equals("ROBOSIM_CDS"));
        pb.environment().putAll(env);
        return pb.start();
    }

    /** Waits for {@code p} (up to {@code seconds}), then for every process of its session; returns its exit code. */
    private static int awaitWithEveryProcess(Process p, String[] cmd, long seconds) throws Exception {
        long session = p.pid(); // setsid execs in place: not a group leader, so its pid is the session id
        String what = String.join(" ", cmd);
        try {
            assertTrue(p.waitFor(seconds, TimeUnit.SECONDS), what + " did not end within " + seconds + " s");
            List<String> left = new ArrayList<>();
            for (ProcessHandle h : inSession(session)) {
                try {
                    h.onExit().get(LINGER_SECONDS, TimeUnit.SECONDS);
                } catch (TimeoutException e) {
                    left.add(h.pid() + " " + h.info().commandLine().orElse("?"));
                }
            }
            assertTrue(left.isEmpty(), what + " left processes running: " + left);
            return p.exitValue();
        } finally {
            p.destroyForcibly();
            inSession(session).forEach(ProcessHandle::destroyForcibly);
        }
    }

    /** Live processes (not zombies) of session {@code sid}, from /proc/PID/stat (Linux). */
    private static List<ProcessHandle> inSession(long sid) {
        return ProcessHandle.allProcesses().filter(h -> {
            try {
                String stat = Files.readString(Path.of("/proc", Long.toString(h.pid()), "stat"), StandardCharsets.UTF_8);
                String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
                return !f[0].equals("Z") && Long.parseLong(f[3]) == sid;
            } catch (IOException gone) {
                return false;
            }
        }).toList();
    }
}
