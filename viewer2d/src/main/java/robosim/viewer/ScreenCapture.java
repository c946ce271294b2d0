package robosim.viewer;

import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Saves the X screen as a PNG, for the screenshot scripts under Xvfb:
 * {@code ScreenCapture FILE.png [--keys UP,LEFT,...]}. With {@code --keys} it first moves the pointer
 * into the top-left window (so it has the keyboard) and types those keys (names as in
 * {@link KeyEvent}'s {@code VK_} constants), half a second apart. The image is trimmed to what is not
 * the empty black screen around the windows.
 */
public final class ScreenCapture {
    private ScreenCapture() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 1 && !(args.length == 3 && args[1].equals("--keys"))) {
            System.err.println("usage: ScreenCapture FILE.png [--keys UP,LEFT,...]");
            System.exit(2);
        }
        Robot robot = new Robot();
        if (args.length == 3) {
            robot.mouseMove(60, 60);
            robot.delay(300);
            for (String name : args[2].split(",")) {
                int code = KeyEvent.class.getField("VK_" + name.trim().toUpperCase(java.util.Locale.ROOT)).getInt(null);
                robot.keyPress(code);
                robot.keyRelease(code);
                robot.delay(500);
            }
            robot.delay(1500);
        }
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        BufferedImage image = trim(robot.createScreenCapture(screen));
        ImageIO.write(image, "png", new File(args[0]));
        System.exit(0);
    }

    /** The smallest top-left region holding every pixel that is not black. */
    private static BufferedImage trim(BufferedImage image) {
        int w = 1;
        int h = 1;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                if ((image.getRGB(x, y) & 0xffffff) != 0) {
                    w = Math.max(w, x + 1);
                    h = Math.max(h, y + 1);
                }
            }
        }
        return image.getSubimage(0, 0, w, h);
    }
}
