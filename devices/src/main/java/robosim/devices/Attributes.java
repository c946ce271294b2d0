package robosim.devices;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/** The attributes the environment file gives one device, as text; remembers which ones the device read. */
public final class Attributes {
    private final Map<String, String> values;
    private final Set<String> read = new LinkedHashSet<>();

    public Attributes(Map<String, String> values) {
        this.values = new LinkedHashMap<>(values);
    }

    /** A number attribute, or {@code otherwise} when absent; not a number is an IllegalArgumentException. */
    public double number(String name, double otherwise) {
        read.add(name);
        String v = values.get(name);
        if (v == null) {
            return otherwise;
        }
        try {
            double d = Double.parseDouble(v.trim());
            if (!Double.isFinite(d)) {
                throw new NumberFormatException();
            }
            return d;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("attribute " + name + " value '" + v + "' is not a number");
        }
    }

    /** A text attribute, or {@code otherwise} when absent. */
    public String text(String name, String otherwise) {
        read.add(name);
        return values.getOrDefault(name, otherwise);
    }

    /** Attributes given but never read: most likely typos. */
    public Set<String> unread() {
        Set<String> left = new LinkedHashSet<>(values.keySet());
        left.removeAll(read);
        return left;
    }
}
