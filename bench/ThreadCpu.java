import java.io.IOException;
import java.nio.file.*;
import java.util.*;

/**
 * Where the CPU of a running benchmark goes, thread by thread: reads /proc (Linux) for every java process
 * and each of its threads twice, SECONDS apart, and prints each thread's user and system CPU (ms) and
 * voluntary context switches (its wakes) over the window, each process's total (which, read from the
 * process's own counters, also holds threads that ended in the window) and the total of all java processes
 * on the machine that are still running at the end (any other java process, such as a build, counts too).
 * usage: javac -d /tmp/threadcpu bench/ThreadCpu.java; java -cp /tmp/threadcpu ThreadCpu [SECONDS]
 * (default 5; compile it first, so that starting it in the middle of a run costs the run no compiling).
 * The kernel counts CPU in ticks of 10 ms (USER_HZ 100), per thread, and splits it into user and system by
 * sampling. A thread or process is known by its id and start time, so an id used again is a new one; one not
 * in the first reading is counted from its start (also a process that became java by exec in the window).
 */
public class ThreadCpu {
    static final String SELF = Long.toString(ProcessHandle.current().pid());

    /** CPU ticks and wakes of one thread, or of a whole process (wakes then unused). */
    record Counters(String label, long userTicks, long sysTicks, long wakes, long started) {}

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && (args[0].equals("--help") || args[0].equals("-h"))) {
            System.out.println("usage: javac -d DIR bench/ThreadCpu.java; java -cp DIR ThreadCpu [SECONDS]  (default 5):"
                    + " CPU and wakes of every java thread over the window");
            return;
        }
        double seconds = args.length > 0 ? seconds(args[0]) : 5;
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
            Counters b = before.getOrDefault(e.getKey(), new Counters(a.label, 0, 0, 0, a.started));
            long user = (a.userTicks - b.userTicks) * 10, sys = (a.sysTicks - b.sysTicks) * 10, wakes = a.wakes - b.wakes;
            threadsOf.merge(processKey(e.getKey()), user + sys, Long::sum);
            if (user + sys > 0 || wakes > 100) {
                System.out.printf("%s user=%d sys=%d wakes=%d%s%n", a.label, user, sys, wakes, began(before, e.getKey()));
            }
        }
        long total = 0;
        for (Map.Entry<String, Counters> e : new TreeMap<>(after).entrySet()) {
            if (e.getKey().contains("/task/")) continue;
            Counters a = e.getValue();
            Counters b = before.getOrDefault(e.getKey(), new Counters(a.label, 0, 0, 0, a.started));
            long cpu = (a.userTicks + a.sysTicks - b.userTicks - b.sysTicks) * 10;
            total += cpu;
            long notInRows = cpu - threadsOf.getOrDefault(e.getKey(), 0L);
            System.out.printf("process %s cpu=%d%s (not in its thread rows: %d: threads that ended, and each row's"
                    + " rounding to 10 ms)%n", a.label, cpu, began(before, e.getKey()), notInRows);
        }
        System.out.printf("all java processes: cpu=%d ms in %.2f s: %.2f cores busy%n", total, window, total / 1000.0 / window);
    }

    /** Every java process's counters, keyed by its /proc directory and start, and each of its threads', under it. */
    static Map<String, Counters> sample() throws IOException {
        Map<String, Counters> samples = new HashMap<>();
        try (DirectoryStream<Path> processes = Files.newDirectoryStream(Path.of("/proc"), "[0-9]*")) {
            for (Path process : processes) {
                String main;
                try {
                    main = mainClass(Files.readString(process.resolve("cmdline")).split("\0"));
                    if (main == null || process.getFileName().toString().equals(SELF)) continue;
                    String label = process.getFileName() + " " + main;
                    Counters whole = read(label, process, false);
                    String processKey = process + "@" + whole.started;
                    samples.put(processKey, whole);
                    try (DirectoryStream<Path> tasks = Files.newDirectoryStream(process.resolve("task"))) {
                        for (Path task : tasks) {
                            try {
                                Counters thread = read(label, task, true);
                                samples.put(processKey + "/task/" + task.getFileName() + "@" + thread.started, thread);
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

    static String began(Map<String, Counters> before, String key) {
        return before.containsKey(key) ? "" : " (began in the window)";
    }

    static double seconds(String arg) {
        try {
            double s = Double.parseDouble(arg);
            if (s > 0 && s <= 3600) return s;
        } catch (NumberFormatException notANumber) {
            // said below
        }
        System.err.println("ThreadCpu: SECONDS must be a number of seconds from 0 to 3600, not \"" + arg + "\"");
        System.exit(2);
        return 0;
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

    /** utime, stime and starttime (fields 14, 15 and 22 of stat, after the name in brackets) and a thread's wakes. */
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
        String label = thread ? processLabel + " " + dir.getFileName() + " [" + name + "]" : processLabel;
        return new Counters(label, Long.parseLong(fields[11]), Long.parseLong(fields[12]), wakes, Long.parseLong(fields[19]));
    }
}
