package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * No blocking work on the JVM's common pool, in the product or in its tests: every
 * {@code CompletableFuture.runAsync} and {@code supplyAsync} in the repository's Java sources names its
 * executor. Without one the task runs on the common pool, whose few workers (one, on a two-core machine,
 * on JDK 21+) a task blocked in a socket read holds, so the next never starts: the soak once waited for
 * ever at "21 of 22" robots that way.
 */
class NoCommonPoolTest {
    private static final Pattern ASYNC = Pattern.compile("\\b(runAsync|supplyAsync)\\s*\\(");

    @Test
    void everyAsyncTaskNamesItsExecutor() throws IOException {
        Path root = Path.of("..").toAbsolutePath().normalize();
        List<String> found = new ArrayList<>();
        try (Stream<Path> files = Files.walk(root)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java") && !p.toString().contains("/target/")
                    && !p.toString().contains("/.git/")).toList()) {
                found.addAll(withoutExecutor(root.relativize(f).toString(), Files.readString(f)));
            }
        }
        assertEquals(List.of(), found, "runAsync/supplyAsync without an executor (the common pool)");
    }

    @Test
    void theCheckFindsACallWithoutAnExecutorAndPassesOneWithIt() {
        String async = "Async("; // (so this file's own text holds no such call)
        String src = "class A { void f() {\n CompletableFuture.run" + async + "() -> g(1, \"a,(b\")); // the robot's\n"
                + " CompletableFuture.supply" + async + "() -> {\n  return h(2, 3);\n }, pool);\n} }";
        assertEquals(List.of("A.java:2 runAsync"), withoutExecutor("A.java", src));
    }

    /** Each call in {@code source} whose argument list has one argument at its top level. */
    static List<String> withoutExecutor(String file, String source) {
        List<String> out = new ArrayList<>();
        Matcher m = ASYNC.matcher(source);
        while (m.find()) {
            int depth = 1;
            int commas = 0;
            int i = m.end();
            for (; i < source.length() && depth > 0; i++) {
                char c = source.charAt(i);
                if (source.startsWith("//", i)) {
                    int end = source.indexOf('\n', i);
                    i = end < 0 ? source.length() : end;
                } else if (source.startsWith("/*", i)) {
                    int end = source.indexOf("*/", i + 2);
                    i = end < 0 ? source.length() : end + 1;
                } else if (c == '"' || c == '\'') {
                    i = skipLiteral(source, i, c);
                } else if (c == '(' || c == '{' || c == '[') {
                    depth++;
                } else if (c == ')' || c == '}' || c == ']') {
                    depth--;
                } else if (c == ',' && depth == 1) {
                    commas++;
                }
            }
            if (commas == 0) {
                int line = 1 + (int) source.substring(0, m.start()).chars().filter(ch -> ch == '\n').count();
                out.add(file + ":" + line + " " + m.group(1));
            }
        }
        return out;
    }

    private static int skipLiteral(String s, int start, char quote) {
        for (int i = start + 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\\') {
                i++;
            } else if (c == quote) {
                return i;
            }
        }
        return s.length();
    }
}
