package robosim.viewer;

import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.image.BufferedImage;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Saves the whole X screen as a PNG ({@code scripts/screenshot-viewer.sh} uses it under Xvfb):
 * {@code ScreenCapture FILE.png}.
 */
public final class ScreenCapture {
    private ScreenCapture() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 1) {
            System.err.println("usage: ScreenCapture FILE.png");
            System.exit(2);
        }
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        BufferedImage image = new Robot().createScreenCapture(screen);
        ImageIO.write(image, "png", new File(args[0]));
        System.exit(0);
    }
}
