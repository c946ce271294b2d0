package robosim.api;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

/**
 * Colours as RoboSim gives them everywhere (LEDs, lights, the floor, objects, a camera's blobs): one {@code int},
 * {@code 0xRRGGBB}, each channel 0 to 255. The named ones are ARGoS's ({@code CColor}), so an experiment ported from
 * ARGoS keeps its colours; {@link #parse} reads a name, {@code #rrggbb} or {@code r,g,b}.
 */
public final class Colours {
    public static final int BLACK = 0x000000;
    public static final int WHITE = 0xFFFFFF;
    public static final int RED = 0xFF0000;
    public static final int GREEN = 0x00FF00;
    public static final int BLUE = 0x0000FF;
    public static final int MAGENTA = 0xFF00FF;
    public static final int CYAN = 0x00FFFF;
    public static final int YELLOW = 0xFFFF00;
    public static final int ORANGE = 0xFF8C00;
    public static final int BROWN = 0xA52A2A;
    public static final int PURPLE = 0xA020F0;
    /** Mid grey, 127 a channel (ARGoS's {@code GRAY50}: the foraging nest's floor). */
    public static final int GRAY50 = 0x7F7F7F;

    private static final Map<String, Integer> NAMED = named();

    private Colours() {
    }

    private static Map<String, Integer> named() {
        Map<String, Integer> m = new LinkedHashMap<>();
        m.put("black", BLACK);
        m.put("white", WHITE);
        m.put("red", RED);
        m.put("green", GREEN);
        m.put("blue", BLUE);
        m.put("magenta", MAGENTA);
        m.put("cyan", CYAN);
        m.put("yellow", YELLOW);
        m.put("orange", ORANGE);
        m.put("brown", BROWN);
        m.put("purple", PURPLE);
        int[] greys = {26, 51, 77, 102, 127, 153, 179, 204, 229};
        for (int i = 0; i < greys.length; i++) {
            m.put("gray" + (i + 1) * 10, rgb(greys[i], greys[i], greys[i]));
        }
        return java.util.Collections.unmodifiableMap(m);
    }

    /** The colour of channels {@code r}, {@code g}, {@code b}, each 0 to 255. */
    public static int rgb(int r, int g, int b) {
        if ((r | g | b) < 0 || r > 255 || g > 255 || b > 255) {
            throw new IllegalArgumentException("a colour's channels are 0 to 255, got " + r + "," + g + "," + b);
        }
        return r << 16 | g << 8 | b;
    }

    public static int red(int rgb) {
        return rgb >> 16 & 0xFF;
    }

    public static int green(int rgb) {
        return rgb >> 8 & 0xFF;
    }

    public static int blue(int rgb) {
        return rgb & 0xFF;
    }

    /** True for a value that is a colour: 0 to {@code 0xFFFFFF}. */
    public static boolean isColour(double value) {
        return value >= 0 && value <= WHITE && value == Math.rint(value);
    }

    /**
     * Its grey level, 0 (black) to 1 (white): {@code (0.299 R + 0.587 G + 0.114 B) / 255}, as ARGoS's ground sensors
     * read the floor.
     */
    public static double grey(int rgb) {
        return (0.299 * red(rgb) + 0.587 * green(rgb) + 0.114 * blue(rgb)) / 255.0;
    }

    /** The names {@link #parse} knows, in order. */
    public static java.util.Set<String> names() {
        return NAMED.keySet();
    }

    /**
     * The colour {@code text} says: a name ({@link #names}, any case), {@code #rrggbb} or {@code r,g,b} (0 to 255).
     *
     * @throws IllegalArgumentException naming the text and the forms it may take
     */
    public static int parse(String text) {
        String t = text == null ? "" : text.trim().toLowerCase(Locale.ROOT);
        Integer named = NAMED.get(t);
        if (named != null) {
            return named;
        }
        try {
            if (t.matches("#[0-9a-f]{6}")) {
                return Integer.parseInt(t.substring(1), 16);
            }
            String[] c = t.split(",", -1);
            if (c.length == 3) {
                return rgb(Integer.parseInt(c[0].trim()), Integer.parseInt(c[1].trim()), Integer.parseInt(c[2].trim()));
            }
        } catch (IllegalArgumentException e) {
            // (not a colour: said below)
        }
        String shown = text == null ? "nothing" : "'" + (text.length() > 40 ? text.substring(0, 40) + "..." : text) + "'";
        throw new IllegalArgumentException(shown.replaceAll("\\p{Cntrl}", "?") + " is not a colour (a name such as "
                + "red, yellow or gray50, #rrggbb, or r,g,b of 0 to 255)");
    }

    /** Its name if it has one ({@code red}), else {@code #rrggbb}. */
    public static String name(int rgb) {
        for (Map.Entry<String, Integer> e : NAMED.entrySet()) {
            if (e.getValue() == rgb) {
                return e.getKey();
            }
        }
        return String.format(Locale.ROOT, "#%06x", rgb & 0xFFFFFF);
    }
}
