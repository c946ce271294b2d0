package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * The arena's floor, as ground sensors read it and viewers draw it: a colour ({@code 0xRRGGBB}), an image stretched
 * over the whole arena on it (optional: its top row along the arena's far edge, largest y), and regions painted on
 * both, each a rectangle, disc or polygon of one colour (a later region over an earlier one). Written inline.
 *
 * @param rgb the colour where no image and no region is
 * @param regions the painted regions, in the order painted
 * @param image null for none
 */
public record Floor(int rgb, List<Region> regions, Image image) {
    /** A white floor, nothing on it: the floor of a world whose file gives none. */
    public static final Floor PLAIN = new Floor(0xFFFFFF, List.of(), null);

    public Floor {
        checkColour(rgb);
        regions = List.copyOf(regions);
    }

    /** This floor with {@code paint} over its regions (what a world's loop functions painted); itself for none. */
    public Floor withPaint(List<Region> paint) {
        if (paint.isEmpty()) {
            return this;
        }
        List<Region> all = new ArrayList<>(regions.size() + paint.size());
        all.addAll(regions);
        all.addAll(paint);
        return new Floor(rgb, all, image);
    }

    /** The colour at world point (x, y), mm, of a floor laid over {@code arena}. */
    public int colourAt(Arena arena, double x, double y) {
        for (int i = regions.size() - 1; i >= 0; i--) {
            Region r = regions.get(i);
            if (r.area().contains(x, y)) {
                return r.rgb();
            }
        }
        return image == null ? rgb : image.at(arena, x, y);
    }

    /** A region of one colour. */
    public record Region(Area area, int rgb) {
        public Region {
            java.util.Objects.requireNonNull(area, "area");
            checkColour(rgb);
        }
    }

    /** Where a region lies, world mm. */
    public sealed interface Area permits Rectangle, Disc, Polygon {
        boolean contains(double x, double y);
    }

    /** An axis-aligned rectangle, its lower-left corner at (x, y). */
    public record Rectangle(double xMm, double yMm, double widthMm, double heightMm) implements Area {
        public Rectangle {
            finite(xMm, yMm);
            if (!(widthMm > 0) || !(heightMm > 0) || Double.isInfinite(widthMm) || Double.isInfinite(heightMm)) {
                throw new IllegalArgumentException("a rectangle's width and height must be > 0, got " + widthMm
                        + " x " + heightMm);
            }
        }

        @Override
        public boolean contains(double x, double y) {
            return x >= xMm && x < xMm + widthMm && y >= yMm && y < yMm + heightMm;
        }
    }

    /** A disc around (x, y). */
    public record Disc(double xMm, double yMm, double radiusMm) implements Area {
        public Disc {
            finite(xMm, yMm);
            if (!(radiusMm > 0) || Double.isInfinite(radiusMm)) {
                throw new IllegalArgumentException("a disc's radius must be > 0, got " + radiusMm);
            }
        }

        @Override
        public boolean contains(double x, double y) {
            double dx = x - xMm;
            double dy = y - yMm;
            return dx * dx + dy * dy < radiusMm * radiusMm;
        }
    }

    /** A polygon, {@code x0, y0, x1, y1, ...}, closed implicitly; a point inside by the even-odd rule. */
    public record Polygon(double[] xyMm) implements Area {
        public Polygon {
            if (xyMm.length < 6 || xyMm.length % 2 != 0) {
                throw new IllegalArgumentException("a polygon needs at least 3 vertices, got " + xyMm.length
                        + " numbers");
            }
            for (double v : xyMm) {
                finite(v, 0);
            }
            xyMm = xyMm.clone();
        }

        @Override
        public double[] xyMm() {
            return xyMm.clone();
        }

        @Override
        public boolean contains(double x, double y) {
            boolean in = false;
            int n = xyMm.length / 2;
            for (int i = 0, j = n - 1; i < n; j = i++) {
                double xi = xyMm[2 * i];
                double yi = xyMm[2 * i + 1];
                double xj = xyMm[2 * j];
                double yj = xyMm[2 * j + 1];
                if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) {
                    in = !in;
                }
            }
            return in;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Polygon p && java.util.Arrays.equals(xyMm, p.xyMm);
        }

        @Override
        public int hashCode() {
            return java.util.Arrays.hashCode(xyMm);
        }
    }

    /** An image, {@code width x height} pixels ({@code 0xRRGGBB}), row by row from its top row. */
    public record Image(int width, int height, int[] rgb) {
        public Image {
            if (width < 1 || height < 1 || (long) width * height > Limits.MAX_FLOOR_PIXELS) {
                throw new IllegalArgumentException("a floor image has 1 to " + Limits.MAX_FLOOR_PIXELS
                        + " pixels, got " + width + " x " + height);
            }
            if (rgb.length != width * height) {
                throw new IllegalArgumentException("a floor image of " + width + " x " + height + " needs "
                        + width * height + " pixels, got " + rgb.length);
            }
            rgb = rgb.clone();
            for (int i = 0; i < rgb.length; i++) {
                rgb[i] &= 0xFFFFFF;
            }
        }

        @Override
        public int[] rgb() {
            return rgb.clone();
        }

        /** The pixel under world point (x, y) of an image stretched over {@code arena} (the edge's at its edge). */
        int at(Arena arena, double x, double y) {
            int col = (int) Math.floor((x - arena.minXMm()) / (arena.maxXMm() - arena.minXMm()) * width);
            int row = (int) Math.floor((arena.maxYMm() - y) / (arena.maxYMm() - arena.minYMm()) * height);
            col = Math.max(0, Math.min(width - 1, col));
            row = Math.max(0, Math.min(height - 1, row));
            return rgb[row * width + col];
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Image i && width == i.width && height == i.height && java.util.Arrays.equals(rgb, i.rgb);
        }

        @Override
        public int hashCode() {
            return java.util.Arrays.hashCode(rgb);
        }
    }

    private static void checkColour(int rgb) {
        if (rgb < 0 || rgb > 0xFFFFFF) {
            throw new IllegalArgumentException("a colour is 0 to 0xFFFFFF, got " + rgb);
        }
    }

    private static void finite(double a, double b) {
        if (!Double.isFinite(a) || !Double.isFinite(b)) {
            throw new IllegalArgumentException("a floor region's coordinates must be finite numbers");
        }
    }

    /** Reads what {@link #writeRegions} wrote, each region checked. */
    static List<Region> readRegions(ObjectInput in) throws IOException {
        try {
            int n = Limits.checkCount("floor region count", in.readInt(), Limits.MAX_FLOOR_REGIONS);
            List<Region> regions = new ArrayList<>(n);
            for (int i = 0; i < n; i++) {
                int colour = in.readInt();
                byte kind = in.readByte();
                Area area = switch (kind) {
                    case RECTANGLE -> new Rectangle(in.readDouble(), in.readDouble(), in.readDouble(), in.readDouble());
                    case DISC -> new Disc(in.readDouble(), in.readDouble(), in.readDouble());
                    case POLYGON -> new Polygon(Wire.readDoubles(in,
                            2 * Limits.checkCount("vertex count", in.readInt(), Limits.MAX_VERTICES)));
                    default -> throw new ProtocolException("a floor region of unknown kind " + kind);
                };
                regions.add(new Region(area, colour));
            }
            return regions;
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }

    private static final byte RECTANGLE = 1;
    private static final byte DISC = 2;
    private static final byte POLYGON = 3;

    void write(ObjectOutput out) throws IOException {
        out.writeInt(rgb);
        writeRegions(out, regions);
        out.writeBoolean(image != null);
        if (image != null) {
            out.writeInt(image.width());
            out.writeInt(image.height());
            for (int p : image.rgb) {
                out.writeInt(p);
            }
        }
    }

    /** Writes a count and each region (a floor's, or what loop functions painted over it). */
    static void writeRegions(ObjectOutput out, List<Region> regions) throws IOException {
        out.writeInt(regions.size());
        for (Region r : regions) {
            out.writeInt(r.rgb());
            if (r.area() instanceof Rectangle a) {
                out.writeByte(RECTANGLE);
                out.writeDouble(a.xMm());
                out.writeDouble(a.yMm());
                out.writeDouble(a.widthMm());
                out.writeDouble(a.heightMm());
            } else if (r.area() instanceof Disc a) {
                out.writeByte(DISC);
                out.writeDouble(a.xMm());
                out.writeDouble(a.yMm());
                out.writeDouble(a.radiusMm());
            } else {
                Polygon a = (Polygon) r.area();
                out.writeByte(POLYGON);
                out.writeInt(a.xyMm.length / 2);
                Wire.writeDoubles(out, a.xyMm, a.xyMm.length);
            }
        }
    }

    static Floor read(ObjectInput in) throws IOException {
        try {
            int base = in.readInt();
            List<Region> regions = readRegions(in);
            Image image = null;
            if (in.readBoolean()) {
                int w = Limits.checkCount("floor image width", in.readInt(), Limits.MAX_FLOOR_PIXELS);
                int h = Limits.checkCount("floor image height", in.readInt(), Limits.MAX_FLOOR_PIXELS);
                if ((long) w * h > Limits.MAX_FLOOR_PIXELS) {
                    throw new ProtocolException("a floor image of " + w + " x " + h + " pixels, at most "
                            + Limits.MAX_FLOOR_PIXELS);
                }
                int[] pixels = new int[w * h];
                for (int i = 0; i < pixels.length; i++) {
                    pixels[i] = in.readInt();
                }
                image = new Image(w, h, pixels);
            }
            return new Floor(base, regions, image);
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}
