package robosim.control;

import com.fasterxml.jackson.databind.JsonNode;
import java.awt.BorderLayout;
import java.awt.Font;
import java.awt.GridLayout;
import java.io.IOException;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.JTextArea;
import javax.swing.SpinnerNumberModel;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import robosim.protocol.SimulationKeys;

/**
 * The Control Panel window: Load..., Start, Stop, Pause, Resume, Step N, Add robot... and Remove robot...
 * buttons, and a live status
 * (state, step, steps/s while running, which robots are connected and which have left, geometry; see
 * {@link StatusText}) polled twice a second. Requests go out on one
 * background thread, never on Swing's; a status poll waits while a long request (step N) runs.
 */
public final class ControlPanelWindow {
    private final String host;
    private final int port;
    private final SimulationKeys keys;
    private final ExecutorService io = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "control-panel-io");
        t.setDaemon(true);
        return t;
    });
    private final JLabel state = new JLabel("connecting...");
    private final JTextArea detail = new JTextArea(6, 44);
    private final JLabel last = new JLabel(" ");
    private final ReplayBar replay = new ReplayBar(this::send);
    private ControlClient client;
    private volatile boolean busy;
    /** The last status reply (null before the first). */
    private volatile JsonNode lastStatus;

    private ControlPanelWindow(String host, int port, SimulationKeys keys) {
        this.host = host;
        this.port = port;
        this.keys = keys;
    }

    /** Opens the window for the Environment at host:port. */
    public static ControlPanelWindow open(String host, int port, SimulationKeys keys) throws Exception {
        ControlPanelWindow w = new ControlPanelWindow(host, port, keys);
        SwingUtilities.invokeAndWait(w::build);
        return w;
    }

    private void build() {
        JFrame frame = new JFrame("RoboSim Control Panel - " + host + ":" + port);
        frame.setDefaultCloseOperation(WindowConstants.EXIT_ON_CLOSE);
        JPanel buttons = new JPanel(new GridLayout(3, 4, 6, 6));
        buttons.add(button("Load...", () -> {
            JFileChooser chooser = new JFileChooser(new java.io.File("test-envs"));
            if (chooser.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
                send("load " + chooser.getSelectedFile().getAbsolutePath());
            }
        }));
        buttons.add(button("Start", () -> send("start")));
        buttons.add(button("Stop", () -> send("stop")));
        buttons.add(button("Pause", () -> send("pause")));
        buttons.add(button("Resume", () -> send("resume")));
        JSpinner steps = new JSpinner(new SpinnerNumberModel(10, 1, 1_000_000, 1));
        buttons.add(steps);
        buttons.add(button("Step", () -> send("step " + steps.getValue())));
        buttons.add(button("Shut down", () -> send("shutdown")));
        buttons.add(button("Add robot...", () -> {
            String request = AddRobotForm.ask(frame);
            if (request != null) {
                send(request);
            }
        }));
        buttons.add(button("Remove robot...", () -> {
            JsonNode status = lastStatus;
            List<String> names = status == null ? List.of() : StatusText.removable(status);
            if (names.isEmpty()) {
                last.setText("remove: no robot takes part now");
                return;
            }
            Object chosen = JOptionPane.showInputDialog(frame, "Remove which robot from the simulation?",
                    "Remove robot", JOptionPane.QUESTION_MESSAGE, null, names.toArray(), names.get(0));
            if (chosen != null) {
                send("remove " + chosen);
            }
        }));
        state.setFont(state.getFont().deriveFont(Font.BOLD, 16f));
        detail.setEditable(false);
        detail.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        JPanel top = new JPanel(new BorderLayout(6, 6));
        top.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        top.add(state, BorderLayout.NORTH);
        top.add(detail, BorderLayout.CENTER);
        top.add(last, BorderLayout.SOUTH);
        JPanel root = new JPanel(new BorderLayout(6, 6));
        root.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        root.add(top, BorderLayout.CENTER);
        JPanel bottom = new JPanel(new BorderLayout(6, 6));
        bottom.add(buttons, BorderLayout.CENTER);
        bottom.add(replay.panel(), BorderLayout.SOUTH);
        root.add(bottom, BorderLayout.SOUTH);
        frame.setContentPane(root);
        frame.pack();
        frame.setLocationByPlatform(true);
        frame.setVisible(true);
        new Timer(500, e -> poll()).start();
        poll();
    }

    private JButton button(String text, Runnable action) {
        JButton b = new JButton(text);
        b.addActionListener(e -> action.run());
        return b;
    }

    private void send(String request) {
        busy = true;
        last.setText(request + " ...");
        io.execute(() -> {
            String shown;
            try {
                JsonNode r = client().request(request);
                shown = request + ": " + (r.path("ok").asBoolean() ? r.path("message").asText("ok")
                        : "refused: " + r.path("error").asText());
            } catch (IOException e) {
                dropClient();
                shown = request + ": " + e.getMessage();
            } finally {
                busy = false;
            }
            String text = shown;
            SwingUtilities.invokeLater(() -> last.setText(text));
        });
    }

    private void poll() {
        if (busy) {
            return;
        }
        io.execute(() -> {
            String head;
            String body;
            JsonNode status = null;
            try {
                JsonNode r = client().request("status");
                status = r;
                lastStatus = r;
                head = StatusText.headline(r);
                body = StatusText.details(r);
            } catch (IOException e) {
                dropClient();
                head = "not connected";
                body = "cannot reach the Environment's control port at " + host + ":" + port + "\n" + e.getMessage();
            }
            String h = head;
            String b = body;
            JsonNode replayed = status;
            SwingUtilities.invokeLater(() -> {
                state.setText(h);
                detail.setText(b);
                if (replay.show(replayed)) {
                    SwingUtilities.getWindowAncestor(state).pack();
                }
            });
        });
    }

    private ControlClient client() throws IOException {
        if (client == null) {
            client = new ControlClient(host, port, keys, 600_000);
        }
        return client;
    }

    private void dropClient() {
        if (client != null) {
            try {
                client.close();
            } catch (IOException ignored) {
                // reconnect at the next poll
            }
            client = null;
        }
    }
}
