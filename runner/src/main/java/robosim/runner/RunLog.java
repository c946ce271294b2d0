package robosim.runner;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A headless run's output as the runner writes it into a file (a sweep's run log, a warm run's): its last lines, the
 * summary line's fields and, for a run that failed, its reason.
 */
public final class RunLog {
    /** The most of a log read from its end, bytes. */
    public static final int TAIL_BYTES = 64 * 1024;
    private final List<String> lines;

    private RunLog(List<String> lines) {
        this.lines = lines;
    }

    /** The last lines of {@code log}, at most {@link #TAIL_BYTES} of it, bytes that are not UTF-8 replaced. */
    public static RunLog read(Path log) throws IOException {
        try (java.io.RandomAccessFile in = new java.io.RandomAccessFile(log.toFile(), "r")) {
            long from = Math.max(0, in.length() - TAIL_BYTES);
            byte[] bytes = new byte[(int) (in.length() - from)];
            in.seek(from);
            in.readFully(bytes);
            List<String> lines = new ArrayList<>(new String(bytes, StandardCharsets.UTF_8).lines().toList());
            if (from > 0 && !lines.isEmpty()) {
                lines.remove(0); // (a line cut in two)
            }
            return new RunLog(lines);
        }
    }

    /** The fields of the runner's summary line ({@code steps=... robots=...}), the last one in its output. */
    public Map<String, String> summary() {
        Map<String, String> fields = new LinkedHashMap<>();
        for (int i = lines.size() - 1; i >= 0; i--) {
            if (lines.get(i).startsWith("steps=")) {
                for (String part : lines.get(i).trim().split("\\s+")) {
                    int eq = part.indexOf('=');
                    if (eq > 0) {
                        fields.put(part.substring(0, eq), part.substring(eq + 1));
                    }
                }
                break;
            }
        }
        return fields;
    }

    /** A failed run's reason: its last line that is neither the summary nor an INFO or DEBUG log line. */
    public String lastError() {
        for (int i = lines.size() - 1; i >= 0; i--) {
            String l = lines.get(i).strip();
            if (!l.isEmpty() && !l.startsWith("steps=") && !l.contains(" INFO ") && !l.contains(" DEBUG ")) {
                return l;
            }
        }
        return "(the run wrote nothing)";
    }
}
