package robosim.control;

import java.awt.GridLayout;
import java.util.Locale;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * The Control Panel's "Add robot..." form: a name, a type, a pose (metres, degrees) and, optionally, a
 * control class (an Environment started with {@code --launch-robots}, as {@code headless.sh} does, then
 * starts its robot process); the request it makes is {@code add NAME TYPE X Y HEADING [CONTROL]}.
 */
final class AddRobotForm {
    private AddRobotForm() {
    }

    /** Asks for the robot on {@code owner}'s screen; the request, or null when cancelled. */
    static String ask(java.awt.Component owner) {
        JTextField name = new JTextField("robot-new", 14);
        JComboBox<String> type = new JComboBox<>(robosim.devices.RobotTypes.names().toArray(new String[0]));
        JTextField x = new JTextField("1.0");
        JTextField y = new JTextField("1.0");
        JTextField heading = new JTextField("0");
        JTextField control = new JTextField("robosim.examples.Wander", 20);
        JPanel form = new JPanel(new GridLayout(0, 2, 6, 4));
        for (Object[] row : new Object[][] {{"name", name}, {"type", type}, {"x (m)", x}, {"y (m)", y},
                {"heading (deg)", heading}, {"control class (optional)", control}}) {
            form.add(new JLabel((String) row[0]));
            form.add((java.awt.Component) row[1]);
        }
        while (JOptionPane.showConfirmDialog(owner, form, "Add robot", JOptionPane.OK_CANCEL_OPTION)
                == JOptionPane.OK_OPTION) {
            try {
                return request(name.getText(), (String) type.getSelectedItem(), x.getText(), y.getText(),
                        heading.getText(), control.getText());
            } catch (IllegalArgumentException e) {
                JOptionPane.showMessageDialog(owner, e.getMessage(), "Add robot", JOptionPane.WARNING_MESSAGE);
            }
        }
        return null;
    }

    /** The request for these fields; a field that cannot be sent is an IllegalArgumentException saying which. */
    static String request(String name, String type, String x, String y, String heading, String control) {
        String n = name.strip();
        if (n.isEmpty() || n.chars().anyMatch(c -> Character.isWhitespace(c) || Character.isISOControl(c))) {
            throw new IllegalArgumentException("the name must be one word, got \"" + n + "\"");
        }
        StringBuilder b = new StringBuilder("add ").append(n).append(' ').append(type);
        for (String[] v : new String[][] {{"x", x}, {"y", y}, {"heading", heading}}) {
            try {
                b.append(' ').append(String.format(Locale.ROOT, "%s", Double.parseDouble(v[1].strip())));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(v[0] + " must be a number, got \"" + v[1] + "\"");
            }
        }
        String c = control.strip();
        if (!c.isEmpty()) {
            if (c.chars().anyMatch(Character::isWhitespace)) {
                throw new IllegalArgumentException("the control class must be one class name, got \"" + c + "\"");
            }
            b.append(' ').append(c);
        }
        return b.toString();
    }
}
