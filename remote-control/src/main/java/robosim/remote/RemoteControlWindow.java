package robosim.remote;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Font;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.ScrollPaneConstants;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import robosim.examples.RobotInfo;
import robosim.protocol.SimulationKeys;

/**
 * The Remote Control window. It drives one robot at a time: the arrows send forward / back /
 * left / right, space sends stop, Tab (or the digit keys) chooses the robot. It shows which robot it
 * drives, whether each robot's link is connected (retried every second) and the robots' replies.
 */
public final class RemoteControlWindow {
    private final List<RobotLink> links = new ArrayList<>();
    private final double stepMm;
    private final double turnDeg;
    private final JLabel driving = new JLabel();
    private final JTextArea robotsView = new JTextArea(5, 40);
    private final JTextArea logArea = new JTextArea(8, 40);
    private final ReplyLog log = new ReplyLog(logArea, ReplyLog.MAX_LINES);
    private int current;

    private RemoteControlWindow(List<RobotInfo> robots, double stepMm, double turnDeg, SimulationKeys keys) {
        this.stepMm = stepMm;
        this.turnDeg = turnDeg;
        for (RobotInfo r : robots) {
            links.add(new RobotLink(r, line -> SwingUtilities.invokeLater(() -> log.append(r.name() + ": " + line)), keys));
        }
    }

    /** Opens the window; {@code keys} are the simulation's (null: none, the robots' links are on loopback). */
    public static RemoteControlWindow open(List<RobotInfo> robots, double stepMm, double turnDeg, SimulationKeys keys)
            throws Exception {
        RemoteControlWindow w = new RemoteControlWindow(robots, stepMm, turnDeg, keys);
        SwingUtilities.invokeAndWait(w::build);
        return w;
    }

    private void build() {
        JFrame frame = new JFrame("RoboSim Remote Control");
        frame.setDefaultCloseOperation(WindowConstants.EXIT_ON_CLOSE);
        driving.setFont(driving.getFont().deriveFont(Font.BOLD, 16f));
        robotsView.setEditable(false);
        robotsView.setFocusable(false);
        robotsView.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        logArea.setEditable(false);
        logArea.setFocusable(false);
        logArea.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        JLabel help = new JLabel(String.format(Locale.ROOT, "<html>Arrows: forward/back %.0f mm, turn %.0f deg. "
                + "Space: stop.<br>Tab or 1-9: choose the robot.</html>", stepMm, turnDeg));
        JPanel root = new JPanel(new BorderLayout(6, 6));
        root.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        JPanel top = new JPanel(new BorderLayout(4, 4));
        top.add(driving, BorderLayout.NORTH);
        top.add(robotsView, BorderLayout.CENTER);
        top.add(help, BorderLayout.SOUTH);
        root.add(top, BorderLayout.NORTH);
        root.add(new JScrollPane(logArea, ScrollPaneConstants.VERTICAL_SCROLLBAR_ALWAYS,
                ScrollPaneConstants.HORIZONTAL_SCROLLBAR_AS_NEEDED), BorderLayout.CENTER);
        frame.setContentPane(root);
        frame.setFocusTraversalKeysEnabled(false);
        frame.addKeyListener(new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                key(e);
            }
        });
        frame.pack();
        frame.setLocationByPlatform(true);
        frame.setVisible(true);
        frame.requestFocus();
        new Timer(1000, e -> refresh()).start();
        refresh();
    }

    private void key(KeyEvent e) {
        String command = switch (e.getKeyCode()) {
            case KeyEvent.VK_UP -> "forward " + (long) stepMm;
            case KeyEvent.VK_DOWN -> "back " + (long) stepMm;
            case KeyEvent.VK_LEFT -> "left " + (long) turnDeg;
            case KeyEvent.VK_RIGHT -> "right " + (long) turnDeg;
            case KeyEvent.VK_SPACE -> "stop";
            default -> null;
        };
        if (e.getKeyCode() == KeyEvent.VK_TAB) {
            current = (current + (e.isShiftDown() ? links.size() - 1 : 1)) % links.size();
            refresh();
            return;
        }
        if (e.getKeyCode() >= KeyEvent.VK_1 && e.getKeyCode() <= KeyEvent.VK_9) {
            int i = e.getKeyCode() - KeyEvent.VK_1;
            if (i < links.size()) {
                current = i;
                refresh();
            }
            return;
        }
        if (command != null) {
            RobotLink link = links.get(current);
            // the network write happens off the Swing thread
            new Thread(() -> {
                boolean sent = link.send(command);
                SwingUtilities.invokeLater(() -> {
                    log.append("-> " + link.robot().name() + ": " + command + (sent ? "" : "  (not connected)"));
                    refresh();
                });
            }, "send").start();
        }
    }

    /** Redraws which robot is driven and each link's state; reconnects links off the Swing thread. */
    private void refresh() {
        RobotLink d = links.get(current);
        driving.setText("Driving " + d.robot().name() + (d.connected() ? "  (connected)" : "  (not connected)"));
        driving.setForeground(d.connected() ? new Color(0, 110, 0) : new Color(170, 0, 0));
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < links.size(); i++) {
            RobotLink l = links.get(i);
            b.append(i == current ? "> " : "  ").append(i + 1).append(' ').append(l.robot().name()).append("  ")
                    .append(l.robot().host()).append(':').append(l.robot().port()).append("  ")
                    .append(l.connected() ? "connected" : "not connected").append('\n');
        }
        robotsView.setText(b.toString());
        new Thread(() -> {
            for (RobotLink l : links) {
                l.ensureConnected();
            }
        }, "connect").start();
    }
}
