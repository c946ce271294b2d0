package robosim.runner;

import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The soak's verdict: every step ran, the robots that left are the ones the faults removed, Geometry
 * was lost and replaced once, every message between two ring robots that were both there to the end
 * arrived exactly once and in order (who listens to whom as each robot says in its own line), and the
 * Environment's heap stayed flat.
 */
record SoakReport(int robots, int robotProcesses, int silentRobots, long steps, long seed, List<String> faults,
        Map<String, String> ringLines) {

    /**
     * Prints the report and returns the exit code (0 PASS, 1 FAIL). {@code killed} is the index of the
     * robot process that was killed, {@code per} the ring robots per process; {@code early} and
     * {@code late} the Environment's old generation after a full GC at 10% and 95% of the run, KB.
     */
    int print(String summary, long early, long late, int killed, int per) {
        Map<String, String> s = HeadlessRunner.fields(summary);
        boolean ok = true;
        System.out.println("soak: " + robots + " ring robots in " + robotProcesses + " processes, " + silentRobots
                + " silent robots, " + steps + " steps, seed " + seed);
        System.out.println("faults injected:");
        for (String f : faults) {
            System.out.println("  - " + f);
        }
        System.out.println("Environment: " + summary);
        ok &= check(Long.parseLong(s.get("steps")) == steps, "every step ran: " + s.get("steps") + " of " + steps);
        int lost = Math.min(robots, (killed + 1) * per) - killed * per;
        ok &= check(Integer.parseInt(s.get("robots_removed")) == lost + silentRobots,
                "robots that left: " + s.get("robots_removed") + " (expected " + lost + " killed + " + silentRobots
                        + " silent)");
        ok &= check(Integer.parseInt(s.get("geometry_losses")) == 1 && Integer.parseInt(s.get("geometry_attaches")) == 1,
                "Geometry lost " + s.get("geometry_losses") + " time(s), a new one attached "
                        + s.get("geometry_attaches") + " time(s)");
        long pairs = 0;
        long delivered = 0;
        int problems = 0;
        for (int i = 0; i < robots; i++) {
            String line = ringLines.get("ring" + i);
            if (line == null) {
                if (ringAlive(i, per, killed)) {
                    ok &= check(false, "ring" + i + " (alive) reported nothing");
                }
                continue;
            }
            Map<String, String> f = HeadlessRunner.fields(line.substring(line.indexOf(' ', 5) + 1));
            problems += Integer.parseInt(f.get("problems"));
            if (!line.contains("problems=0")) {
                ok &= check(false, line);
            }
            // who this robot listens to, as it says itself: a ring robot, or a robot that never sends
            String from = f.get("from");
            long received = Long.parseLong(f.get("received"));
            int sender = from.startsWith("ring") ? Integer.parseInt(from.substring(4)) : -1;
            if (sender < 0 && received != 0) {
                ok &= check(false, "ring" + i + " received " + received + " messages from " + from + ", which sends none");
            } else if (sender >= 0 && ringAlive(i, per, killed) && ringAlive(sender, per, killed)) {
                pairs++;
                delivered += received;
                if (received != steps) {
                    ok &= check(false, "ring" + i + " received " + received + " of " + steps + " messages from " + from);
                }
            }
        }
        ok &= check(problems == 0, "messages out of order, repeated or from the wrong robot: " + problems);
        ok &= check(true, "messages between robots both there to the end: " + delivered + " delivered over " + pairs
                + " pairs, " + steps + " each (exactly once, in order)");
        if (early > 0 && late > 0) {
            double growth = (late - early) * 100.0 / early;
            // within 10%, or 2 MB for a short run's small heap (a killed process, a new Geometry between the reads)
            ok &= check(Math.abs(growth) <= 10 || Math.abs(late - early) <= 2048, String.format(Locale.ROOT,
                    "Environment old generation after a full GC: %d KB at 10%%, %d KB at 95%% (%+.1f%%)", early, late,
                    growth));
        } else {
            ok &= check(false, "the Environment's heap could not be read (jcmd)");
        }
        System.out.println(ok ? "soak: PASS" : "soak: FAIL");
        return ok ? 0 : 1;
    }

    /** True if ring robot {@code i} was there to the end (its process was not the one killed). */
    private static boolean ringAlive(int i, int per, int killed) {
        return i / per != killed;
    }

    private static boolean check(boolean holds, String what) {
        System.out.println((holds ? "  ok   " : "  FAIL ") + what);
        return holds;
    }
}
