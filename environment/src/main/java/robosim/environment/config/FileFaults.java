package robosim.environment.config;

import java.util.Comparator;
import java.util.TreeSet;
import robosim.protocol.Printable;

/**
 * The faults found in one environment file, for one {@link EnvironmentFileException}: each one line
 * {@code FILE:LINE:COLUMN: what is wrong} (the line and column where the element at fault starts), or
 * {@code FILE: what is wrong} for a fault of no one place (an empty file, a {@code --param} the file does not have).
 * Shown in file order, those of no place first; the first {@link #SHOWN} of them, then one line
 * {@code ... and N more}. Only those shown are kept, however many the file has.
 */
final class FileFaults {
    /** How many faults the exception's message shows at most. */
    static final int SHOWN = 20;

    private static final Comparator<Fault> IN_FILE_ORDER = Comparator
            .comparingInt((Fault f) -> f.at() == null ? 0 : f.at().line())
            .thenComparingInt(f -> f.at() == null ? 0 : f.at().column())
            .thenComparingInt(Fault::found);

    private final String file;
    /** The first {@link #SHOWN} faults in file order. */
    private final TreeSet<Fault> first = new TreeSet<>(IN_FILE_ORDER);
    private int count;
    /** How places in the text read (its placeholders replaced) are the file's: none until {@link #placedBy}. */
    private Placeholders.Columns columns;

    /** One fault: where, the how-manieth found, and its line. */
    private record Fault(FilePosition at, int found, String line) {
    }

    /** Faults of {@code file}, as its name is shown. */
    FileFaults(String file) {
        this.file = file;
    }

    /**
     * A name from the file as a fault's line shows it: at most 64 characters, control characters as '?' (a fault
     * line repeats its element's name, so a name of megabytes must not be copied into every one).
     */
    static String cut(String name) {
        return Printable.of(name, 64);
    }

    /** A fault at {@code at} (null: of no one place); {@code what} is shown on one line, control characters as '?'. */
    void add(FilePosition at, String what) {
        FilePosition place = columns == null ? at : columns.inFile(at);
        first.add(new Fault(place, count, Printable.of(file + (place == null ? "" : ":" + place) + ": " + what)));
        count++;
        if (first.size() > SHOWN) {
            first.pollLast();
        }
    }

    /** Faults added from now on are at places in the text as read, its placeholders replaced as {@code c} says. */
    void placedBy(Placeholders.Columns c) {
        columns = c;
    }

    /** Throws every fault found, if there is one. */
    void throwIfAny() throws EnvironmentFileException {
        if (count > 0) {
            throw exception();
        }
    }

    /** The faults found (at least one), each on a line, in file order. */
    EnvironmentFileException exception() {
        StringBuilder message = new StringBuilder();
        for (Fault f : first) {
            message.append(message.length() == 0 ? "" : "\n").append(f.line());
        }
        if (count > SHOWN) {
            message.append("\n... and ").append(count - SHOWN).append(" more");
        }
        return new EnvironmentFileException(message.toString());
    }
}
