package robosim.sweep;

import java.io.PrintStream;
import java.util.Locale;

/**
 * The sweep's progress on stderr: runs done, failed, and the time left at the pace so far. On a terminal a bar
 * redrawn in place; otherwise (a log, CI) a line at every tenth of the runs. Called from the runs' threads.
 */
final class Progress {
    private static final int BAR = 30;
    private final PrintStream err;
    private final boolean terminal;
    private final int total;
    private final long start = System.nanoTime();
    private int done;
    private int failed;
    private int lastTenth;

    Progress(int total, PrintStream err, boolean terminal) {
        this.total = total;
        this.err = err;
        this.terminal = terminal;
    }

    /** A run has a row (failed or not). */
    void finished(boolean ok) {
        String line;
        synchronized (this) {
            done++;
            if (!ok) {
                failed++;
            }
            int tenth = total == 0 ? 10 : done * 10 / total;
            if (terminal) {
                line = "\r" + text() + (done == total ? "\n" : "");
            } else if (tenth > lastTenth || done == total) {
                lastTenth = tenth;
                line = text() + "\n";
            } else {
                line = null;
            }
        }
        if (line != null) { // (printed outside the lock: a stream may block)
            err.print(line);
            err.flush();
        }
    }

    /** A line for the user between the progress lines (on a terminal, on a line of its own above the bar). */
    void say(String line) {
        String text;
        synchronized (this) {
            text = (terminal && done > 0 && done < total ? "\r\033[K" : "") + line + "\n"
                    + (terminal && done > 0 && done < total ? "\r" + text() : "");
        }
        err.print(text);
        err.flush();
    }

    /** Ends a bar left open (the sweep stopped early). */
    void close() {
        boolean open;
        synchronized (this) {
            open = terminal && done < total;
        }
        if (open) {
            err.println();
        }
    }

    private String text() {
        int filled = total == 0 ? BAR : done * BAR / total;
        double elapsed = (System.nanoTime() - start) / 1e9;
        long left = done == 0 ? -1 : Math.round(elapsed / done * (total - done));
        return String.format(Locale.ROOT, "sweep: [%s%s] %d/%d runs, %d failed, %s left", "#".repeat(filled),
                ".".repeat(BAR - filled), done, total, failed, left < 0 ? "?" : clock(left));
    }

    private static String clock(long seconds) {
        return seconds >= 3600 ? String.format(Locale.ROOT, "%d:%02d:%02d", seconds / 3600, seconds / 60 % 60, seconds % 60)
                : String.format(Locale.ROOT, "%d:%02d", seconds / 60, seconds % 60);
    }
}
