package robosim.remote;

import javax.swing.JTextArea;
import javax.swing.text.BadLocationException;
import javax.swing.text.DefaultCaret;
import javax.swing.text.Element;

/**
 * The Remote Control's log of commands and replies: a text area (shown in a scroll pane) that keeps
 * the newest {@code maxLines} lines, drops the oldest beyond that, and moves its caret to the end
 * after every line so the scroll pane shows the newest one. Swing thread only.
 */
final class ReplyLog {
    /** Lines kept by the window; older ones are dropped. */
    static final int MAX_LINES = 500;

    private final JTextArea area;
    private final int maxLines;

    ReplyLog(JTextArea area, int maxLines) {
        if (maxLines < 1) {
            throw new IllegalArgumentException("maxLines must be >= 1, got " + maxLines);
        }
        this.area = area;
        this.maxLines = maxLines;
        // follow the caret even though the area never has the focus (the keys go to the window)
        ((DefaultCaret) area.getCaret()).setUpdatePolicy(DefaultCaret.ALWAYS_UPDATE);
    }

    /** Appends one line (line breaks in it are shown as spaces) and scrolls to it. */
    void append(String line) {
        area.append(line.replace('\n', ' ').replace('\r', ' ') + "\n");
        Element root = area.getDocument().getDefaultRootElement();
        // the text ends with a line break, so the last element is the empty line after it
        int excess = root.getElementCount() - 1 - maxLines;
        if (excess > 0) {
            try {
                area.getDocument().remove(0, root.getElement(excess - 1).getEndOffset());
            } catch (BadLocationException e) {
                throw new IllegalStateException("the log's own offsets are out of range", e);
            }
        }
        area.setCaretPosition(area.getDocument().getLength());
    }

    /** The lines kept, oldest first. */
    int lineCount() {
        return area.getDocument().getDefaultRootElement().getElementCount() - 1;
    }
}
