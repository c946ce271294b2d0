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
 * (a value holds no line break), so a later error's line number is the file's.
 */
final class Placeholders {
    /** What a parameter's name may be: 1 to 64 of {@code A-Z a-z 0-9 _ . -}, not a digit first. */
    static final Pattern NAME = Pattern.compile("[A-Za-z_][A-Za-z0-9_.-]{0,63}");
    /** {@code $${} (a literal), or {@code ${name}} / {@code ${name:default}} within one line, nothing nested. */
    private static final Pattern PLACEHOLDER = Pattern.compile("\\$\\$\\{|\\$\\{([^}:\\n\\r${]*)(?::([^}\\n\\r${]*))?}");

    /** The file's text with every placeholder replaced, and the names it held. */
    record Replaced(String text, Set<String> names) {
    }

    private Placeholders() {
    }

    /** Replaces every placeholder of {@code text} (from file {@code where}); one line naming the first fault. */
    static Replaced replace(String where, String text, Map<String, String> given) throws EnvironmentFileException {
        Set<String> names = new TreeSet<>();
        Matcher m = PLACEHOLDER.matcher(text);
        StringBuilder out = new StringBuilder(text.length());
        int from = 0;
        while (m.find()) {
            unclosed(where, text, from, m.start());
            if (m.group().equals("$${")) {
                out.append(text, from, m.start()).append("${");
                from = m.end();
                continue;
            }
            String name = m.group(1);
            if (!NAME.matcher(name).matches()) {
                throw new EnvironmentFileException(where + at(text, m.start()) + ": '" + robosim.protocol.Printable.of(m.group(), 80)
                        + "' is not a placeholder: a name is 1 to 64 letters, digits, '_', '.' or '-', not a digit first");
            }
            String value;
            if (given.containsKey(name)) {
                value = escaped(given.get(name));
            } else if (m.group(2) != null) {
                value = m.group(2);
            } else {
                throw new EnvironmentFileException(where + at(text, m.start()) + ": ${" + name + "} has no default (write ${"
                        + name + ":VALUE}) and no value was given for it (--param " + name + "=VALUE)");
            }
            if (value.indexOf('\n') >= 0 || value.indexOf('\r') >= 0) {
                throw new EnvironmentFileException(where + at(text, m.start()) + ": the value of ${" + name
                        + "} holds a line break");
            }
            names.add(name);
            out.append(text, from, m.start()).append(value);
            from = m.end();
        }
        unclosed(where, text, from, text.length());
        out.append(text, from, text.length());
        return new Replaced(out.toString(), names);
    }

    /** A {@code ${} between {@code from} and {@code to} is not a placeholder: it is not closed on its line, or nests. */
    private static void unclosed(String where, String text, int from, int to) throws EnvironmentFileException {
        int open = text.indexOf("${", from);
        if (open >= 0 && open < to) {
            throw new EnvironmentFileException(where + at(text, open) + ": '${' without its closing '}' on its line "
                    + "(placeholders do not nest; $${ is a '${' of the file's own)");
        }
    }

    /** {@code :line:column} of offset {@code i}, both from 1 (counted only for an error's line). */
    private static String at(String text, int i) {
        int line = 1;
        int lineStart = 0;
        for (int k = 0; k < i; k++) {
            if (text.charAt(k) == '\n') {
                line++;
                lineStart = k + 1;
            }
        }
        return ":" + line + ":" + (i - lineStart + 1);
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
