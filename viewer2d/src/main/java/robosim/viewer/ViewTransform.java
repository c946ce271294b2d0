package robosim.viewer;

import robosim.protocol.Arena;

/**
 * World (mm, y up) to screen (pixels, y down): screen = offset + scale * world, with y flipped.
 * Zoom keeps the point under the cursor fixed. Mutable; used on the Swing thread only.
 */
public final class ViewTransform {
    private static final double MIN_SCALE = 1e-4;
    private static final double MAX_SCALE = 10;

    private double scale = 0.05;
    private double offsetX;
    private double offsetY;

    /** Pixels per millimetre. */
    public double scale() {
        return scale;
    }

    public double toScreenX(double xMm) {
        return offsetX + scale * xMm;
    }

    public double toScreenY(double yMm) {
        return offsetY - scale * yMm;
    }

    public double toWorldX(double px) {
        return (px - offsetX) / scale;
    }

    public double toWorldY(double py) {
        return (offsetY - py) / scale;
    }

    /** Fits the arena into a width x height pixel area with a small margin, centred. */
    public void fit(Arena arena, int width, int height) {
        fit(arena, width, height, 12);
    }

    /** Fits the arena into a width x height pixel area, {@code margin} pixels clear all round at least, centred. */
    public void fit(Arena arena, int width, int height, double margin) {
        double w = arena.maxXMm() - arena.minXMm();
        double h = arena.maxYMm() - arena.minYMm();
        scale = clamp(Math.min((width - 2 * margin) / w, (height - 2 * margin) / h));
        offsetX = (width - scale * w) / 2 - scale * arena.minXMm();
        offsetY = (height + scale * h) / 2 + scale * arena.minYMm();
    }

    /** Multiplies the scale by {@code factor}, keeping the world point under (px, py) in place. */
    public void zoomAt(double px, double py, double factor) {
        double wx = toWorldX(px);
        double wy = toWorldY(py);
        scale = clamp(scale * factor);
        offsetX = px - scale * wx;
        offsetY = py + scale * wy;
    }

    public void pan(double dxPixels, double dyPixels) {
        offsetX += dxPixels;
        offsetY += dyPixels;
    }

    private static double clamp(double s) {
        return Math.max(MIN_SCALE, Math.min(MAX_SCALE, s));
    }
}
