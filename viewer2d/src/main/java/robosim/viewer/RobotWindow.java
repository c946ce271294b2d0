package robosim.viewer;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import robosim.protocol.RobotView;

/**
 * The robot-specific viewer: one robot's window ({@link RobotRenderer} above, its message log below),
 * fed by its own connection that watches that robot ({@link RobotFeed}). A Swing timer polls the feed
 * each frame, on the Swing thread; closing the window closes the connection (or, when it is the
 * process's only window, ends the process).
 */
final class RobotWindow {
    private final JFrame frame;
    private final RobotFeed feed;
    private final JTextArea log = new JTextArea();
    private final Timer timer;
    private Scene scene;
    private RobotView view;
    private int robot = -1;
    private long logShown = -1;

    private final JPanel panel = new JPanel() {
        private static final long serialVersionUID = 1L;

        @Override
        protected void paintComponent(Graphics g) {
            super.paintComponent(g);
            if (scene != null && robot >= 0) {
                RobotRenderer.render((Graphics2D) g, scene, robot, view, getWidth(), getHeight());
            }
        }
    };

    private RobotWindow(String title, RobotFeed feed, int fps, boolean only, Runnable closed) {
        this.feed = feed;
        frame = new JFrame(title);
        panel.setPreferredSize(new Dimension(760, 440));
        log.setEditable(false);
        log.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        JSplitPane split = new JSplitPane(JSplitPane.VERTICAL_SPLIT, panel, new JScrollPane(log));
        split.setResizeWeight(0.75);
        split.setDividerLocation(440);
        frame.setLayout(new BorderLayout());
        frame.add(split, BorderLayout.CENTER);
        frame.setSize(780, 620);
        frame.setDefaultCloseOperation(only ? WindowConstants.EXIT_ON_CLOSE : WindowConstants.DISPOSE_ON_CLOSE);
        timer = new Timer(Math.max(1, 1000 / fps), e -> refresh());
        frame.addWindowListener(new java.awt.event.WindowAdapter() {
            @Override
            public void windowClosed(java.awt.event.WindowEvent e) {
                timer.stop();
                closed.run();
            }
        });
        timer.start();
    }

    /**
     * Opens a robot window on the Swing thread; {@code only}: it is the process's one window (closing it
     * ends the process); {@code closed}: run when it is closed (closes its connection).
     */
    static void open(String title, RobotFeed feed, int fps, boolean only, Runnable closed) {
        SwingUtilities.invokeLater(() -> {
            RobotWindow w = new RobotWindow(title, feed, fps, only, closed);
            if (!only) {
                w.frame.setLocationByPlatform(true);
            }
            w.frame.setVisible(true);
        });
    }

    private void refresh() {
        Scene s = feed.latest();
        RobotView v = feed.view();
        if (s != null && (s != scene || v != view)) {
            scene = s;
            view = v;
            robot = s.names().indexOf(feed.name());
            frame.setTitle(feed.name() + " - " + StatusLine.state(s));
            panel.repaint();
        }
        if (s == null) {
            frame.setTitle(feed.name() + " - " + feed.lastLine()); // (connecting, or refused)
        }
        long logged = feed.logged();
        if (logged != logShown) {
            logShown = logged;
            log.setText(String.join("\n", feed.log()));
            log.setCaretPosition(log.getDocument().getLength());
        }
    }
}
