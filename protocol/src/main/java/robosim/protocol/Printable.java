package robosim.protocol;

/** Text from the network made safe for one log line: every control character (a line break) shown as '?'. */
public final class Printable {
    private Printable() {
    }

    public static String of(String text) {
        if (text == null) {
            return "";
        }
        StringBuilder out = new StringBuilder(text.length());
        text.codePoints().forEach(c -> out.appendCodePoint(Character.isISOControl(c) ? '?' : c));
        return out.toString();
    }

    /** As {@link #of}, at most {@code max} characters of it ("..." after when cut). */
    public static String of(String text, int max) {
        if (text == null || text.length() <= max) {
            return of(text);
        }
        return of(text.substring(0, max)) + "..."; // (cut first: a long text costs no more than its head)
    }
}
