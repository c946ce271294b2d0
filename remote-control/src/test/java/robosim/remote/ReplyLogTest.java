package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.swing.JTextArea;
import org.junit.jupiter.api.Test;

/** The Remote Control's log: bounded, newest last, caret (and so the scroll pane) at the newest line. */
class ReplyLogTest {
    static {
        System.setProperty("java.awt.headless", "true");
    }

    @Test
    void keepsTheNewestLinesAndEndsAtTheNewest() {
        JTextArea area = new JTextArea();
        ReplyLog log = new ReplyLog(area, 5);
        for (int i = 1; i <= 12; i++) {
            log.append("rc1: done forward 250 #" + i);
            assertEquals(area.getDocument().getLength(), area.getCaretPosition(), "caret after line " + i);
        }
        assertEquals(5, log.lineCount());
        assertEquals("rc1: done forward 250 #8\nrc1: done forward 250 #9\nrc1: done forward 250 #10\n"
                + "rc1: done forward 250 #11\nrc1: done forward 250 #12\n", area.getText());
    }

    @Test
    void aLineBreakFromTheNetworkDoesNotMakeTwoLines() {
        JTextArea area = new JTextArea();
        ReplyLog log = new ReplyLog(area, 3);
        log.append("rc2: error not a command: \"x\ny\"");
        assertEquals(1, log.lineCount());
        assertTrue(area.getText().startsWith("rc2: error not a command: \"x y\""), area.getText());
    }

    @Test
    void belowOneLineIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new ReplyLog(new JTextArea(), 0));
    }
}
