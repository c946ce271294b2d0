package robosim.protocol;

/**
 * Text from the network made safe for one log line: every control character (a line break), line or paragraph
 * separator (U+2028, U+2029) and format character (a bidirectional override such as U+202E, which would show the rest
 * of the line reversed) shown as '?'.
 */
public final class Printable {
    private Printable() {
    }

    public static String of(String text) {
        if (text == null) {
            return "";
        }
        StringBuilder out = new StringBuilder(text.length());
        text.codePoints().forEach(c -> out.appendCodePoint(safe(c) ? c : '?'));
        return out.toString();
    }

    private static boolean safe(int c) {
        int type = Character.getType(c);
        return !Character.isISOControl(c) && type != Character.LINE_SEPARATOR && type != Character.PARAGRAPH_SEPARATOR
                && type != Character.FORMAT;
    }

    /** As {@link #of}, at most {@code max} characters of it ("..." after when cut). */
    public static String of(String text, int max) {
        if (text == null || text.length() <= max) {
            return of(text);
        }
        return of(text.substring(0, max)) + "..."; // (cut first: a long text costs no more than its head)
    }
}
