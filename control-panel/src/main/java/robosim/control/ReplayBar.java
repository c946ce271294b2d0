package robosim.control;

import com.fasterxml.jackson.databind.JsonNode;
import java.awt.BorderLayout;
import java.util.function.Consumer;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;

/**
 * The Control Panel's row for a replay ({@code scripts/replay.sh}), shown once a status reply says
 * {@code "replay":true}: a timeline from the first to the last recorded step (let go of it to seek there)
 * and the speed, 0.1 to 100 times real time. Swing's thread only.
 */
final class ReplayBar {
    private static final String[] SPEEDS = {"0.1", "0.25", "0.5", "1", "2", "5", "10", "25", "50", "100"};

    private final Consumer<String> send;
    private final JPanel panel = new JPanel(new BorderLayout(6, 6));
    private final JSlider timeline = new JSlider(0, 0, 0);
    private final JComboBox<String> speed = new JComboBox<>(SPEEDS);
    private final JLabel at = new JLabel(" ");
    private boolean updating;

    ReplayBar(Consumer<String> send) {
        this.send = send;
        speed.setSelectedItem("1");
        speed.setToolTipText("times real time");
        timeline.addChangeListener(e -> {
            if (!updating && !timeline.getValueIsAdjusting()) {
                send.accept("seek " + timeline.getValue());
            }
        });
        speed.addActionListener(e -> {
            if (!updating) {
                send.accept("speed " + speed.getSelectedItem());
            }
        });
        panel.add(new JLabel("replay"), BorderLayout.WEST);
        panel.add(timeline, BorderLayout.CENTER);
        JPanel right = new JPanel(new BorderLayout(4, 4));
        right.add(at, BorderLayout.WEST);
        right.add(speed, BorderLayout.EAST);
        panel.add(right, BorderLayout.EAST);
        panel.setVisible(false);
    }

    JPanel panel() {
        return panel;
    }

    /** Shows what a status reply says of the replay; true if the row has just appeared (the window packs). */
    boolean show(JsonNode status) {
        if (status == null || !status.path("replay").asBoolean(false)) {
            return false;
        }
        boolean appeared = !panel.isVisible();
        panel.setVisible(true);
        if (timeline.getValueIsAdjusting()) {
            return appeared; // (the user is dragging it)
        }
        updating = true;
        try {
            int first = (int) Math.max(Integer.MIN_VALUE, status.path("first_step").asLong());
            int last = (int) Math.min(Integer.MAX_VALUE, status.path("last_step").asLong());
            timeline.setMinimum(Math.min(first, last));
            timeline.setMaximum(last);
            timeline.setValue((int) Math.max(first, Math.min(last, status.path("step").asLong())));
            at.setText(status.path("step").asLong() + " / " + last);
            String x = String.valueOf(status.path("speed").asDouble());
            for (String s : SPEEDS) {
                if (Double.parseDouble(s) == Double.parseDouble(x) && !s.equals(speed.getSelectedItem())) {
                    speed.setSelectedItem(s);
                }
            }
        } finally {
            updating = false;
        }
        return appeared;
    }
}
