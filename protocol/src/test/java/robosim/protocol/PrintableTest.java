package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class PrintableTest {
    @Test
    void whatCouldBreakOrTurnALogLineIsShownAsAQuestionMark() {
        assertEquals("a?b?c?d?e?f", Printable.of("a\nb\rc\u0085d\u2028e\u2029f"), "line breaks of every kind");
        assertEquals("ok ?gnp.exe", Printable.of("ok \u202Egnp.exe"), "a bidirectional override");
        assertEquals("?[31mred", Printable.of("\u001B[31mred"), "a terminal's escape");
        assertEquals("Zürich 東京 🤖", Printable.of("Zürich 東京 🤖"), "letters and symbols as they are");
    }

    @Test
    void aLongTextIsCutToItsHead() {
        assertEquals("abc...", Printable.of("abcdef", 3));
        assertEquals("abc", Printable.of("abc", 3));
        assertEquals("", Printable.of(null, 3));
    }
}
