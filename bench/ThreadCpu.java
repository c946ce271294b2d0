import java.io.IOException;
import java.nio.file.*;
import java.util.*;

/**
 * Where the CPU of a running benchmark goes, thread by thread: reads /proc (Linux) for every thread of
 * every java process twice, SECONDS apart, and prints each thread's user and system CPU (ms) and voluntary
 * context switches (its wakes) over the window, then each process's total and the machine's.
 * usage: java bench/ThreadCpu.java [SECONDS]   (default 5; start it in the middle of a long run)
 * The kernel counts CPU in ticks of 10 ms (USER_HZ 100), so each thread's figure is within 10 ms.
 */
public class ThreadCpu {
    static final String SELF = Long.toString(ProcessHandle.current().pid());

    record Sample(long pid, String main, String thread, long userTicks, long sysTicks, long wakes) {}

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && (args[0].equals("--help") || args[0].equals("-h"))) {
            System.out.println("usage: java bench/ThreadCpu.java [SECONDS]  (default 5): CPU and wakes of every java thread over the window");
            return;
        }
        double seconds = args.length > 0 ? Double.parseDouble(args[0]) : 5;
        Map<String, Sample> before = sample();
        long t0 = System.nanoTime();
        Thread.sleep((long) (seconds * 1000));
        Map<String, Sample> after = sample();
        double window = (System.nanoTime() - t0) / 1e9;
        System.out.printf("window %.2f s; CPU in ms (ticks of 10 ms); wakes = voluntary context switches%n", window);
        Map<String, long[]> perProcess = new TreeMap<>();
        long total = 0;
        for (Map.Entry<String, Sample> e : new TreeMap<>(after).entrySet()) {
            Sample b = before.get(e.getKey());
            if (b == null) continue;
            Sample a = e.getValue();
            long user = (a.userTicks - b.userTicks) * 10, sys = (a.sysTicks - b.sysTicks) * 10, wakes = a.wakes - b.wakes;
            total += user + sys;
            perProcess.computeIfAbsent(a.pid + " " + a.main, k -> new long[1])[0] += user + sys;
            if (user + sys > 0 || wakes > 100) {
                System.out.printf("%d %s [%s] user=%d sys=%d wakes=%d%n", a.pid, a.main, a.thread, user, sys, wakes);
            }
        }
        perProcess.forEach((process, cpu) -> System.out.printf("process %s cpu=%d%n", process, cpu[0]));
        System.out.printf("total cpu=%d ms in %.2f s: %.2f cores busy%n", total, window, total / 1000.0 / window);
    }

    static Map<String, Sample> sample() throws IOException {
        Map<String, Sample> samples = new HashMap<>();
        try (DirectoryStream<Path> processes = Files.newDirectoryStream(Path.of("/proc"), "[0-9]*")) {
            for (Path process : processes) {
                try {
                    String main = mainClass(Files.readString(process.resolve("cmdline")).split("\0"));
                    if (main == null || process.getFileName().toString().equals(SELF)) continue;
                    try (DirectoryStream<Path> tasks = Files.newDirectoryStream(process.resolve("task"))) {
                        for (Path task : tasks) {
                            Sample s = read(Long.parseLong(process.getFileName().toString()), main, task);
                            samples.put(task.toString(), s);
                        }
                    }
                } catch (IOException | RuntimeException gone) {
                    // the process or thread ended between listing and reading: not in this window
                }
            }
        }
        return samples;
    }

    /** The main class (or -jar file) of a java command line, or null for anything else. */
    static String mainClass(String[] cmd) {
        if (cmd.length == 0 || !cmd[0].endsWith("java")) return null;
        for (int i = 1; i < cmd.length; i++) {
            String arg = cmd[i];
            if (arg.equals("-cp") || arg.equals("-classpath") || arg.equals("--class-path")) { i++; continue; }
            if (arg.equals("-jar") && i + 1 < cmd.length) return Path.of(cmd[i + 1]).getFileName().toString();
            if (arg.startsWith("-")) continue;
            if (arg.endsWith(".java")) return Path.of(arg).getFileName().toString().replace(".java", "");
            return arg.substring(arg.lastIndexOf('.') + 1);
        }
        return "?";
    }

    static Sample read(long pid, String main, Path task) throws IOException {
        String stat = Files.readString(task.resolve("stat"));
        String name = stat.substring(stat.indexOf('(') + 1, stat.lastIndexOf(')'));
        String[] fields = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        long wakes = 0;
        for (String line : Files.readAllLines(task.resolve("status"))) {
            if (line.startsWith("voluntary_ctxt_switches")) wakes = Long.parseLong(line.split("\\s+")[1]);
        }
        return new Sample(pid, main, name, Long.parseLong(fields[11]), Long.parseLong(fields[12]), wakes);
    }
}
