import java.io.IOException;
import java.nio.file.*;
import java.util.*;

/**
 * Where the CPU of a running benchmark goes, thread by thread: reads /proc (Linux) for every java process
 * and each of its threads twice, SECONDS apart, and prints each thread's user and system CPU (ms) and
 * voluntary context switches (its wakes) over the window, each process's total (which, read from the
 * process's own counters, also holds threads that ended in the window) and the total of all java processes.
 * usage: javac -d /tmp/threadcpu bench/ThreadCpu.java; java -cp /tmp/threadcpu ThreadCpu [SECONDS]
 * (default 5; compile it first, so that starting it in the middle of a run costs the run no compiling).
 * The kernel counts CPU in ticks of 10 ms (USER_HZ 100) and splits it into user and system by sampling.
 */
public class ThreadCpu {
    static final String SELF = Long.toString(ProcessHandle.current().pid());

    /** CPU ticks and wakes of one thread, or of a whole process (wakes then unused). */
    record Counters(String label, long userTicks, long sysTicks, long wakes) {}

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && (args[0].equals("--help") || args[0].equals("-h"))) {
            System.out.println("usage: java -cp DIR ThreadCpu [SECONDS]  (default 5): CPU and wakes of every java thread over the window");
            return;
        }
        double seconds = args.length > 0 ? Double.parseDouble(args[0]) : 5;
        long t0 = System.nanoTime();
        Map<String, Counters> before = sample();
        Thread.sleep((long) (seconds * 1000));
        long t1 = System.nanoTime();
        Map<String, Counters> after = sample();
        double window = (t1 - t0) / 1e9;
        System.out.printf("window %.2f s; CPU in ms (ticks of 10 ms); wakes = voluntary context switches%n", window);
        Map<String, Long> threadsOf = new TreeMap<>();
        for (Map.Entry<String, Counters> e : new TreeMap<>(after).entrySet()) {
            if (!e.getKey().contains("/task/")) continue;
            Counters a = e.getValue();
            Counters b = before.getOrDefault(e.getKey(), new Counters(a.label, 0, 0, 0));
            long user = (a.userTicks - b.userTicks) * 10, sys = (a.sysTicks - b.sysTicks) * 10, wakes = a.wakes - b.wakes;
            threadsOf.merge(processKey(e.getKey()), user + sys, Long::sum);
            if (user + sys > 0 || wakes > 100) {
                String began = before.containsKey(e.getKey()) ? "" : " (began in the window)";
                System.out.printf("%s user=%d sys=%d wakes=%d%s%n", a.label, user, sys, wakes, began);
            }
        }
        long total = 0;
        for (Map.Entry<String, Counters> e : new TreeMap<>(after).entrySet()) {
            if (e.getKey().contains("/task/")) continue;
            Counters a = e.getValue();
            Counters b = before.getOrDefault(e.getKey(), new Counters(a.label, 0, 0, 0));
            long cpu = (a.userTicks + a.sysTicks - b.userTicks - b.sysTicks) * 10;
            total += cpu;
            long ended = cpu - threadsOf.getOrDefault(e.getKey(), 0L);
            System.out.printf("process %s cpu=%d (threads that ended in the window: %d)%n", a.label, cpu, Math.max(0, ended));
        }
        System.out.printf("all java processes: cpu=%d ms in %.2f s: %.2f cores busy%n", total, window, total / 1000.0 / window);
    }

    /** Every java process's counters, keyed by its /proc directory, and each of its threads', keyed by the thread's. */
    static Map<String, Counters> sample() throws IOException {
        Map<String, Counters> samples = new HashMap<>();
        try (DirectoryStream<Path> processes = Files.newDirectoryStream(Path.of("/proc"), "[0-9]*")) {
            for (Path process : processes) {
                String main;
                try {
                    main = mainClass(Files.readString(process.resolve("cmdline")).split("\0"));
                    if (main == null || process.getFileName().toString().equals(SELF)) continue;
                    String label = process.getFileName() + " " + main;
                    samples.put(process.toString(), read(label, process, false));
                    try (DirectoryStream<Path> tasks = Files.newDirectoryStream(process.resolve("task"))) {
                        for (Path task : tasks) {
                            try {
                                samples.put(task.toString(), read(label, task, true));
                            } catch (IOException | RuntimeException ended) {
                                // this thread ended between listing and reading; its process's counters keep its CPU
                            }
                        }
                    }
                } catch (IOException | RuntimeException ended) {
                    // the process ended between listing and reading: not in this sample
                }
            }
        }
        return samples;
    }

    static String processKey(String taskPath) {
        return taskPath.substring(0, taskPath.indexOf("/task/"));
    }

    /** The main class (or -jar file, or source file) of a java command line, or null for anything else. */
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

    /** utime and stime (fields 14 and 15 of stat, after the name in brackets) and, for a thread, its wakes. */
    static Counters read(String processLabel, Path dir, boolean thread) throws IOException {
        String stat = Files.readString(dir.resolve("stat"));
        String name = stat.substring(stat.indexOf('(') + 1, stat.lastIndexOf(')'));
        String[] fields = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        long wakes = 0;
        if (thread) {
            for (String line : Files.readAllLines(dir.resolve("status"))) {
                if (line.startsWith("voluntary_ctxt_switches")) wakes = Long.parseLong(line.split("\\s+")[1]);
            }
        }
        String label = thread ? processLabel + " [" + name + "]" : processLabel;
        return new Counters(label, Long.parseLong(fields[11]), Long.parseLong(fields[12]), wakes);
    }
}
