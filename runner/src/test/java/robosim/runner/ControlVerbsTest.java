package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import robosim.control.ControlPanelMain;
import robosim.environment.control.ControlVerb;
import robosim.environment.control.EnvironmentCommands;
import robosim.environment.replay.ReplayCommands;

/**
 * A control verb is declared once, where it is served ({@link ControlVerb}); what tells users about the verbs is
 * held to those declarations: the Control Panel's {@code --help} lists every request of the Environment, with its
 * help, in the declared order, and those a replay serves beside them, and the protocol's page has a row for each of
 * the Environment's and says which are answered at once.
 */
class ControlVerbsTest {
    private static final Path REPO = Path.of("..").toAbsolutePath().normalize();

    private static List<ControlVerb> environment() {
        return new EnvironmentCommands(null, null).verbs();
    }

    private static List<ControlVerb> replay() {
        return new ReplayCommands(null, null).verbs();
    }

    @Test
    void theControlPanelsHelpListsEveryRequestWithItsHelpInTheDeclaredOrder() {
        String usage = new CommandLine(new ControlPanelMain()).getUsageMessage().replaceAll("\\s+", " ");
        int requests = usage.indexOf("Requests: ");
        int replays = usage.indexOf("Of a replay also: ");
        assertTrue(requests >= 0 && replays > requests, usage);
        List<String> listed = entries(usage.substring(requests + "Requests: ".length(), replays));
        assertEquals(environment().stream().map(v -> v.usage() + ": " + v.help()).toList(), listed,
                "the Environment's requests, each with its help");
        Set<String> environmentUsages = environment().stream().map(ControlVerb::usage).collect(Collectors.toSet());
        String rest = usage.substring(replays + "Of a replay also: ".length());
        List<String> replayOnly = entries(rest.substring(0, rest.indexOf('.') + 1));
        assertEquals(replay().stream().filter(v -> !environmentUsages.contains(v.usage()))
                .map(v -> v.usage() + ": " + v.help()).toList(), replayOnly, "what a replay serves beside them");
    }

    /** "a: b; c: d." as ["a: b", "c: d"]. */
    private static List<String> entries(String sentence) {
        String s = sentence.strip();
        return List.of((s.endsWith(".") ? s.substring(0, s.length() - 1) : s).split("; "));
    }

    @Test
    void theProtocolPageHasARowForEachRequestAndSaysWhichAreAnsweredAtOnce() throws IOException {
        String page = Files.readString(REPO.resolve("protocol/README.md"), StandardCharsets.UTF_8);
        String port = page.substring(page.indexOf("**Control port**"), page.indexOf("**Remote-control link**"));
        Set<String> rows = new TreeSet<>();
        Matcher row = Pattern.compile("(?m)^\\| `([^`]+)` \\|").matcher(port);
        while (row.find()) {
            rows.add(row.group(1));
        }
        Set<String> declared = environment().stream().map(ControlVerb::usage).collect(Collectors.toCollection(TreeSet::new));
        declared.addAll(List.of("challenge", "prove HEX"));
        assertEquals(declared, rows, "the control port's table, one row a request");

        Matcher sentence = Pattern.compile("((?:`[a-z]+`(?:, | and )?)+) answer at once[^;]*; ((?:`[a-z]+`(?:, | and )?)+) "
                + "are carried out one at a time").matcher(port.replaceAll("\\s+", " "));
        assertTrue(sentence.find(), "the sentence that says which requests are answered at once");
        assertEquals(names(environment(), false), words(sentence.group(1)), "answered at once");
        assertEquals(names(environment(), true), words(sentence.group(2)), "carried out one at a time");
    }

    private static Set<String> names(List<ControlVerb> verbs, boolean waits) {
        return verbs.stream().filter(v -> v.waits() == waits).map(ControlVerb::name)
                .collect(Collectors.toCollection(TreeSet::new));
    }

    private static Set<String> words(String quoted) {
        Set<String> words = new TreeSet<>();
        Matcher m = Pattern.compile("`([a-z]+)`").matcher(quoted);
        while (m.find()) {
            words.add(m.group(1));
        }
        return words;
    }
}
