package robosim.viewer;

import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.image.BufferedImage;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Saves the X screen as a PNG ({@code scripts/screenshot-viewer.sh} and
 * {@code scripts/screenshot-panels.sh} use it under Xvfb): {@code ScreenCapture FILE.png [WIDTH HEIGHT]}
 * (the top-left WIDTH x HEIGHT pixels; the whole screen without them).
 */
public final class ScreenCapture {
    private ScreenCapture() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 1 && args.length != 3) {
            System.err.println("usage: ScreenCapture FILE.png [WIDTH HEIGHT]");
            System.exit(2);
        }
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        if (args.length == 3) {
            screen = screen.intersection(new Rectangle(0, 0, Integer.parseInt(args[1]), Integer.parseInt(args[2])));
        }
        BufferedImage image = new Robot().createScreenCapture(screen);
        ImageIO.write(image, "png", new File(args[0]));
        System.exit(0);
    }
}
