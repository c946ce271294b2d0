package robosim.environment.net;

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
}
