package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Every log line a doc quotes is one the code prints. A doc (any {@code *.md} of the repository) marks a
 * quoted log line in one of two ways:
 * <ul>
 * <li>a fenced block whose info string is {@code log}: each non-blank line is one log line, which may start with
 * its level ({@code INFO}, {@code WARN}, {@code ERROR});</li>
 * <li>a code span right after its level: {@code WARN `robot r1 left at step 20 (...)`}.</li>
 * </ul>
 * In a quoted line these stand for values: {@code ...}; a word in capitals ({@code N}, {@code NAME}, {@code HOST});
 * a word with a digit in it ({@code ring2}, {@code 1000}); a word with a dot or a slash inside, a file or class name
 * ({@code test-envs/test.xml}, {@code java.util.HashMap}, {@code 0.35}); a class's simple name in CamelCase
 * ({@code RobotHello}); a word in brackets, a thread's number or name ({@code [2]}, {@code [#1]}). Each piece of
 * text left between them must be text the code writes: part of one string literal of a main Java source, or,
 * where the piece runs across values the code puts in ({@code {}}, {@code %s}, a {@code +} after a literal), the
 * end of one literal, any whole ones a value follows, and the start of another. The level is not checked, nor
 * whether the pieces of one line come from one message.
 */
class QuotedLogLinesTest {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();
    private static final Pattern FENCE = Pattern.compile("(?m)^[ \\t]*```log[ \\t]*\\n(.*?)^[ \\t]*```",
            Pattern.DOTALL);
    private static final Pattern INLINE = Pattern.compile("\\b(?:INFO|WARN|ERROR)\\s+`([^`]+)`");
    private static final Pattern LEVEL = Pattern.compile("^(?:INFO|WARN|ERROR)\\s+");
    /** What stands for a value in a quoted line. */
    private static final Pattern VALUE = Pattern.compile("\\.\\.\\.|…|\\[[^]\\s]*]|[\\w\\-]+(?:[./][\\w\\-]+)+"
            + "|[\\w\\-]*\\d[\\w\\-]*|\\b[A-Z][A-Z_]*\\b|\\b[A-Z][a-z]+(?:[A-Z][a-z0-9]*)+\\b");
    /** Where the code puts a value into a literal. */
    private static final Pattern HOLE = Pattern.compile("\\{}|%[-#+ 0,(]*\\d*(?:\\.\\d+)?[a-zA-Z]");

    @Test
    void everyQuotedLogLineIsOneTheCodePrints() throws IOException {
        List<Segment> segments = segmentsOfTheCode();
        List<String> wrong = new ArrayList<>();
        int quoted = 0;
        for (Path doc : docs()) {
            for (String line : quotedLogLines(Files.readString(doc, StandardCharsets.UTF_8))) {
                quoted++;
                String unprinted = firstUnprintedPiece(line, segments);
                if (unprinted != null) {
                    wrong.add(REPO.relativize(doc) + ": `" + line + "`: the code prints no \"" + unprinted + "\"");
                }
            }
        }
        assertTrue(quoted >= 20, "the docs quote " + quoted + " log lines: is the marking still found?");
        assertEquals(List.of(), wrong, "quoted log lines the code does not print");
    }

    @Test
    void aLineTheCodeDoesNotPrintIsFound() throws IOException {
        List<Segment> segments = segmentsOfTheCode();
        assertEquals(null, firstUnprintedPiece("a new Geometry process attached: geometry is resolved there again",
                segments));
        assertEquals("a new Geometry process attached at step", firstUnprintedPiece(
                "a new Geometry process attached at step 12: geometry is resolved there again", segments));
        assertEquals(null, firstUnprintedPiece("robot r1 left at step 20 (did not take a write within 500 ms); it is "
                + "removed from the world and the others go on", segments), "across the values the code puts in");
        assertEquals(List.of("a second line", "the third", "robot r1 left at step 20 (...)"), quotedLogLines(
                "WARN `robot r1 left at step 20 (...)` and `not this`\n"
                + "```log\nINFO a second line\n\nthe third\n```\n"));
    }

    /** The log lines a doc quotes, each on one line. */
    static List<String> quotedLogLines(String doc) {
        List<String> lines = new ArrayList<>();
        Matcher fence = FENCE.matcher(doc);
        while (fence.find()) {
            for (String line : fence.group(1).split("\n")) {
                if (!line.isBlank()) {
                    lines.add(LEVEL.matcher(line.strip()).replaceFirst(""));
                }
            }
        }
        Matcher inline = INLINE.matcher(doc);
        while (inline.find()) {
            lines.add(inline.group(1).strip().replaceAll("\\s+", " "));
        }
        return lines;
    }

    /** The first piece of the line (between its values) that the code does not print, or null. */
    static String firstUnprintedPiece(String line, List<Segment> segments) {
        for (String piece : VALUE.split(line)) {
            String p = piece.strip().replaceAll("\\s+", " ");
            if (p.chars().anyMatch(Character::isLetter) && !printed(p, segments)) {
                return p;
            }
        }
        return null;
    }

    /**
     * Inside one segment; or, across the values the code puts in, the end of one segment, any whole ones a value
     * follows, and the start of one, where at each seam a value follows the segment before it or comes before the
     * one after it.
     */
    private static boolean printed(String piece, List<Segment> segments) {
        if (segments.stream().anyMatch(s -> s.text().contains(piece))) {
            return true;
        }
        Map<String, Boolean> known = new HashMap<>();
        for (int i = 1; i < piece.length(); i++) {
            String head = piece.substring(0, i);
            for (boolean open : new boolean[] {true, false}) {
                if (segments.stream().anyMatch(s -> s.valueAfter() == open && s.text().endsWith(head))
                        && goesOn(piece, i, open, segments, known)) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Whether the piece from {@code at} on is whole segments a value follows, then the start of one. */
    private static boolean goesOn(String piece, int at, boolean valueBefore, List<Segment> segments,
            Map<String, Boolean> known) {
        String key = at + "/" + valueBefore;
        Boolean k = known.get(key);
        if (k != null) {
            return k;
        }
        known.put(key, false);
        String rest = piece.substring(at);
        boolean yes = false;
        for (Segment s : segments) {
            String t = s.text();
            boolean seam = valueBefore || s.valueBefore();
            boolean whole = s.valueAfter() && !t.isEmpty() && t.length() < rest.length() && rest.startsWith(t);
            if (seam && (t.startsWith(rest) || (whole && goesOn(piece, at + t.length(), true, segments, known)))) {
                yes = true;
                break;
            }
        }
        known.put(key, yes);
        return yes;
    }

    /** Text of a string literal between the values the code puts in, and whether a value comes before and after it. */
    record Segment(String text, boolean valueBefore, boolean valueAfter) {
    }

    /** A string literal, and whether a {@code +} comes before and after it. */
    record Literal(String text, boolean valueBefore, boolean valueAfter) {
    }

    /** Every string literal of the main Java sources ("a" + "b" joined), cut at the values put into it. */
    static List<Segment> segmentsOfTheCode() throws IOException {
        List<Segment> segments = new ArrayList<>();
        try (Stream<Path> files = Files.walk(REPO)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java") && p.toString().contains("/src/main/java/")
                    && !p.toString().contains("/target/")).toList()) {
                for (Literal literal : literals(Files.readString(f, StandardCharsets.UTF_8))) {
                    String[] parts = HOLE.split(literal.text(), -1);
                    for (int k = 0; k < parts.length; k++) {
                        segments.add(new Segment(parts[k], k > 0 || literal.valueBefore(),
                                k < parts.length - 1 || literal.valueAfter()));
                    }
                }
            }
        }
        return segments;
    }

    /** The string literals of one Java source, unescaped; literals joined by {@code +} alone are one. */
    static List<Literal> literals(String java) {
        List<Literal> out = new ArrayList<>();
        int i = 0;
        int n = java.length();
        int lastEnd = -1;
        while (i < n) {
            char c = java.charAt(i);
            if (c == '/' && i + 1 < n && java.charAt(i + 1) == '/') {
                i = java.indexOf('\n', i) < 0 ? n : java.indexOf('\n', i);
            } else if (c == '/' && i + 1 < n && java.charAt(i + 1) == '*') {
                i = java.indexOf("*/", i + 2) < 0 ? n : java.indexOf("*/", i + 2) + 2;
            } else if (c == '\'') {
                i = java.indexOf('\'', java.charAt(i + 1) == '\\' ? i + 3 : i + 2) + 1;
            } else if (java.startsWith("\"\"\"", i)) {
                int end = java.indexOf("\"\"\"", i + 3);
                String text = java.substring(java.indexOf('\n', i) + 1, end);
                boolean before = plusBefore(java, i);
                i = end + 3;
                out.add(new Literal(text, before, plusAfter(java, i)));
                lastEnd = -1;
            } else if (c == '"') {
                int start = i;
                StringBuilder s = new StringBuilder();
                i++;
                while (java.charAt(i) != '"') {
                    if (java.charAt(i) == '\\') {
                        char e = java.charAt(i + 1);
                        if (e == 'u') {
                            s.append((char) Integer.parseInt(java.substring(i + 2, i + 6), 16));
                            i += 6;
                            continue;
                        }
                        s.append(switch (e) {
                            case 'n' -> '\n';
                            case 't' -> '\t';
                            case 'r' -> '\r';
                            case '0' -> '\0';
                            default -> e;
                        });
                        i += 2;
                    } else {
                        s.append(java.charAt(i++));
                    }
                }
                i++;
                if (lastEnd >= 0 && java.substring(lastEnd, start).matches("(?s)\\s*\\+\\s*")) {
                    Literal joined = out.get(out.size() - 1);
                    out.set(out.size() - 1, new Literal(joined.text() + s, joined.valueBefore(), plusAfter(java, i)));
                } else {
                    out.add(new Literal(s.toString(), plusBefore(java, start), plusAfter(java, i)));
                }
                lastEnd = i;
            } else {
                i++;
            }
        }
        return out;
    }

    /** Whether the next thing from {@code at} on, past white space, is a {@code +}. */
    private static boolean plusAfter(String java, int at) {
        int i = at;
        while (i < java.length() && Character.isWhitespace(java.charAt(i))) {
            i++;
        }
        return i < java.length() && java.charAt(i) == '+';
    }

    /** Whether the last thing before {@code at}, past white space, is a {@code +}. */
    private static boolean plusBefore(String java, int at) {
        int i = at - 1;
        while (i >= 0 && Character.isWhitespace(java.charAt(i))) {
            i--;
        }
        return i >= 0 && java.charAt(i) == '+';
    }

    private static List<Path> docs() {
        try (Stream<Path> files = Files.walk(REPO)) {
            return files.filter(p -> p.toString().endsWith(".md"))
                    .filter(p -> !p.toString().contains("/target/") && !p.toString().contains("/node_modules/")
                            && !p.toString().contains("/.git/"))
                    .sorted().toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
