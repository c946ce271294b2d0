package robosim.viewer;

import java.awt.BorderLayout;
import javax.swing.BorderFactory;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;

/**
 * The viewer's window: the world and a status line ({@link StatusLine}). A Swing
 * timer polls the {@link SceneFeed} for the newest immutable scene each frame, on the Swing thread.
 */
final class ViewerWindow {
    private final JFrame frame;
    private final WorldPanel panel;
    private final JLabel status = new JLabel("connecting ...");
    private Scene shown;

    private ViewerWindow(String title, SceneFeed feed, SceneRenderer.Options options, int fps,
            java.util.function.Consumer<String> robotClicked) {
        frame = new JFrame(title);
        panel = new WorldPanel(options);
        panel.onRobotClicked(robotClicked);
        status.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        frame.setLayout(new BorderLayout());
        frame.add(panel, BorderLayout.CENTER);
        frame.add(status, BorderLayout.SOUTH);
        frame.setDefaultCloseOperation(WindowConstants.EXIT_ON_CLOSE);
        frame.pack();
        frame.setLocationRelativeTo(null);
        Timer timer = new Timer(Math.max(1, 1000 / fps), e -> refresh(feed.latest()));
        timer.start();
    }

    /** Opens the window on the Swing thread; {@code robotClicked} gets the name of a robot clicked on. */
    static void open(String title, SceneFeed feed, SceneRenderer.Options options, int fps,
            java.util.function.Consumer<String> robotClicked) {
        SwingUtilities.invokeLater(() -> {
            ViewerWindow w = new ViewerWindow(title, feed, options, fps, robotClicked);
            w.frame.setVisible(true);
            w.panel.requestFocusInWindow();
        });
    }

    private void refresh(Scene s) {
        if (s == null || s == shown) {
            return;
        }
        shown = s;
        panel.show(s);
        status.setText(StatusLine.text(s));
    }
}
