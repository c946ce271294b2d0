package robosim.viewer;

import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import javax.swing.JPanel;

/**
 * The drawing area: shows the current {@link Scene} through a {@link ViewTransform}. Mouse: wheel
 * zooms at the cursor, drag pans, double-click fits, a click on a robot opens its robot window. Keys: f fit, + and - zoom, arrows pan,
 * t trails, s sonar, n names. Swing thread only.
 */
final class WorldPanel extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient ViewTransform transform = new ViewTransform();
    private transient Scene scene;
    private transient SceneRenderer.Options options;
    private boolean autoFit = true;
    private transient java.util.function.Consumer<String> robotClicked = name -> { };
    private int dragX;
    private int dragY;

    WorldPanel(SceneRenderer.Options options) {
        this.options = options;
        setPreferredSize(new Dimension(900, 600));
        setFocusable(true);
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                dragX = e.getX();
                dragY = e.getY();
                requestFocusInWindow();
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                transform.pan(e.getX() - dragX, e.getY() - dragY);
                dragX = e.getX();
                dragY = e.getY();
                autoFit = false;
                repaint();
            }

            @Override
            public void mouseClicked(MouseEvent e) {
                if (e.getClickCount() == 2) {
                    fit();
                } else if (e.getClickCount() == 1) {
                    String robot = robotAt(e.getX(), e.getY());
                    if (robot != null) {
                        robotClicked.accept(robot);
                    }
                }
            }

            @Override
            public void mouseWheelMoved(MouseWheelEvent e) {
                transform.zoomAt(e.getX(), e.getY(), Math.pow(1.15, -e.getPreciseWheelRotation()));
                autoFit = false;
                repaint();
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
        addKeyListener(new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                key(e);
            }
        });
    }

    /** What a click on a robot does (given its name): the viewer opens that robot's window. */
    void onRobotClicked(java.util.function.Consumer<String> action) {
        robotClicked = action;
    }

    /** The robot drawn at this pixel (within its disc, or 6 px of its centre when it is drawn smaller), or null. */
    private String robotAt(int px, int py) {
        if (scene == null) {
            return null;
        }
        for (int i = 0; i < scene.robotCount() && i < scene.poses().count(); i++) {
            double dx = transform.toScreenX(scene.poses().xMm(i)) - px;
            double dy = transform.toScreenY(scene.poses().yMm(i)) - py;
            double r = Math.max(6, scene.robots().get(i).radiusMm() * transform.scale());
            if (dx * dx + dy * dy <= r * r) {
                return scene.names().get(i);
            }
        }
        return null;
    }

    private void key(KeyEvent e) {
        switch (e.getKeyCode()) {
            case KeyEvent.VK_F -> fit();
            case KeyEvent.VK_PLUS, KeyEvent.VK_EQUALS, KeyEvent.VK_ADD -> zoom(1.25);
            case KeyEvent.VK_MINUS, KeyEvent.VK_SUBTRACT -> zoom(0.8);
            case KeyEvent.VK_LEFT -> pan(40, 0);
            case KeyEvent.VK_RIGHT -> pan(-40, 0);
            case KeyEvent.VK_UP -> pan(0, 40);
            case KeyEvent.VK_DOWN -> pan(0, -40);
            case KeyEvent.VK_T -> options = new SceneRenderer.Options(options.names(), !options.trails(), options.sonar());
            case KeyEvent.VK_S -> options = new SceneRenderer.Options(options.names(), options.trails(), !options.sonar());
            case KeyEvent.VK_N -> options = new SceneRenderer.Options(!options.names(), options.trails(), options.sonar());
            default -> {
                return;
            }
        }
        repaint();
    }

    private void zoom(double factor) {
        transform.zoomAt(getWidth() / 2.0, getHeight() / 2.0, factor);
        autoFit = false;
    }

    private void pan(double dx, double dy) {
        transform.pan(dx, dy);
        autoFit = false;
    }

    void fit() {
        autoFit = true;
        if (scene != null) {
            transform.fit(scene.arena(), getWidth(), getHeight());
        }
        repaint();
    }

    void show(Scene s) {
        scene = s;
        repaint();
    }

    @Override
    protected void paintComponent(Graphics g) {
        super.paintComponent(g);
        if (scene == null) {
            return;
        }
        if (autoFit) {
            transform.fit(scene.arena(), getWidth(), getHeight());
        }
        SceneRenderer.render((Graphics2D) g, scene, transform, options, getWidth(), getHeight());
    }
}
