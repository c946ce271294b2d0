package robosim.environment.config;

import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The placeholders of an environment file, {@code ${name}} and {@code ${name:default}}, replaced before the
 * file is read: by the value given for the name ({@code --param name=value}, a sweep's), else by the default
 * as written. A given value is escaped for XML (it is text, never markup); a default is part of the file and
 * taken as written. A placeholder without a default needs a value. {@code $${} is a {@code ${} of the file's own
 * (not a placeholder). Placeholders are found anywhere, comments included. Replacing keeps every line where it was
 * (a value holds no line break), so a later error's line number is the file's; its column is the file's through
 * {@link Columns} (a place inside a value is the placeholder's).
 */
final class Placeholders {
    /** What a parameter's name may be: 1 to 64 of {@code A-Z a-z 0-9 _ . -}, not a digit first. */
    static final Pattern NAME = Pattern.compile("[A-Za-z_][A-Za-z0-9_.-]{0,63}");
    /** {@code $${} (a literal), or {@code ${name}} / {@code ${name:default}} within one line, nothing nested. */
    private static final Pattern PLACEHOLDER = Pattern.compile("\\$\\$\\{|\\$\\{([^}:\\n\\r${]*)(?::([^}\\n\\r${]*))?}");

    /** The file's text with every placeholder replaced, the names it held, and where its columns were the file's. */
    record Replaced(String text, Set<String> names, Columns columns) {
    }

    /**
     * Where each replacement moved a line's columns: a place in the replaced text is taken back to the file's (one
     * inside a replaced value to where its placeholder starts).
     */
    static final class Columns {
        /** Per line: each replacement's {out start, out end, file start, file end} columns, in line order. */
        private final Map<Integer, java.util.List<int[]>> byLine = new java.util.HashMap<>();

        private void replaced(int line, int outStart, int outEnd, int fileStart, int fileEnd) {
            byLine.computeIfAbsent(line, k -> new java.util.ArrayList<>())
                    .add(new int[] {outStart, outEnd, fileStart, fileEnd});
        }

        /** The file's place of {@code at}, a place in the replaced text (null stays null). */
        FilePosition inFile(FilePosition at) {
            java.util.List<int[]> on = at == null ? null : byLine.get(at.line());
            if (on == null) {
                return at;
            }
            int shift = 0;
            for (int[] r : on) {
                if (at.column() < r[0]) {
                    break;
                }
                if (at.column() < r[1]) {
                    return new FilePosition(at.line(), r[2]);
                }
                shift = r[3] - r[1];
            }
            return new FilePosition(at.line(), at.column() + shift);
        }
    }

    private Placeholders() {
    }

    /**
     * Replaces every placeholder of {@code text}; each fault is recorded in {@code faults} (the text is then of no
     * use). The rest of a line after a {@code ${} that is not closed on it is not read for placeholders.
     */
    static Replaced replace(FileFaults faults, String text, Map<String, String> given) {
        Set<String> names = new TreeSet<>();
        Columns columns = new Columns();
        Lines lines = new Lines(text);
        int shiftLine = 0;
        int shift = 0; // (how far this line's replacements so far moved its columns)
        Matcher m = PLACEHOLDER.matcher(text);
        StringBuilder out = new StringBuilder(text.length());
        int from = 0;
        while (m.find(from)) {
            int open = text.indexOf("${", from);
            if (open >= 0 && open < m.start()) {
                faults.add(lines.at(open), unclosed());
                from = lines.end(open);
                continue;
            }
            out.append(text, from, m.start());
            from = m.end();
            FilePosition at = lines.at(m.start());
            if (at.line() != shiftLine) {
                shiftLine = at.line();
                shift = 0;
            }
            if (m.group().equals("$${")) {
                out.append("${");
                columns.replaced(at.line(), at.column() + shift, at.column() + shift + 2, at.column(), at.column() + 3);
                shift -= 1;
                continue;
            }
            String name = m.group(1);
            if (!NAME.matcher(name).matches()) {
                faults.add(lines.at(m.start()), "'" + robosim.protocol.Printable.of(m.group(), 80) + "' is not a "
                        + "placeholder: a name is 1 to 64 letters, digits, '_', '.' or '-', not a digit first");
                continue;
            }
            String value;
            if (given.containsKey(name)) {
                value = escaped(given.get(name));
            } else if (m.group(2) != null) {
                value = m.group(2);
            } else {
                faults.add(lines.at(m.start()), "${" + name + "} has no default (write ${" + name + ":VALUE}) and no "
                        + "value was given for it (--param " + name + "=VALUE)");
                continue;
            }
            if (value.indexOf('\n') >= 0 || value.indexOf('\r') >= 0) {
                faults.add(lines.at(m.start()), "the value of ${" + name + "} holds a line break");
                continue;
            }
            names.add(name);
            out.append(value);
            columns.replaced(at.line(), at.column() + shift, at.column() + shift + value.length(), at.column(),
                    at.column() + m.group().length());
            shift += value.length() - m.group().length();
        }
        for (int open = text.indexOf("${", from); open >= 0; open = text.indexOf("${", lines.end(open))) {
            faults.add(lines.at(open), unclosed());
        }
        out.append(text, from, text.length());
        return new Replaced(out.toString(), names, columns);
    }

    private static String unclosed() {
        return "'${' without its closing '}' on its line (placeholders do not nest; $${ is a '${' of the file's own)";
    }

    /**
     * Line and column of offsets of one text, asked in increasing order (faults are found so), so counting them costs
     * one pass over the text however many faults it has.
     */
    private static final class Lines {
        private final String text;
        private int counted;
        private int line = 1;
        private int lineStart;

        Lines(String text) {
            this.text = text;
        }

        /** Where offset {@code i} is; at least the offset asked before. */
        FilePosition at(int i) {
            for (; counted < i; counted++) {
                if (text.charAt(counted) == '\n') {
                    line++;
                    lineStart = counted + 1;
                }
            }
            return new FilePosition(line, i - lineStart + 1);
        }

        /** The offset where the line of offset {@code i} ends (its line break, or the end of the text). */
        int end(int i) {
            int end = text.indexOf('\n', i);
            return end < 0 ? text.length() : end;
        }
    }

    private static String escaped(String value) {
        StringBuilder b = new StringBuilder(value.length());
        for (char c : value.toCharArray()) {
            switch (c) {
                case '&' -> b.append("&amp;");
                case '<' -> b.append("&lt;");
                case '>' -> b.append("&gt;");
                case '"' -> b.append("&quot;");
                case '\'' -> b.append("&apos;");
                default -> b.append(c);
            }
        }
        return b.toString();
    }
}
