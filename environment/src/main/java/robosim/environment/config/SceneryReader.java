package robosim.environment.config;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import robosim.api.Colours;
import robosim.environment.core.Placement;
import robosim.protocol.Floor;
import robosim.protocol.Light;
import robosim.protocol.Limits;
import robosim.protocol.WorldObject;

/**
 * The {@code <floor>}, {@code <lights>} and {@code <objects>} of an environment file, metres to millimetres, each
 * checked, each fault recorded at its element as one line: a colour that is not one, a floor image that is not a PNG,
 * cannot be read or is too large, a light below the floor, an object of no size or overlapping what was placed before
 * it ({@link Placement}).
 */
final class SceneryReader {
    private static final double MM_PER_M = 1000.0;
    /** The largest floor image file, bytes. */
    static final long MAX_IMAGE_BYTES = 16L * 1024 * 1024;
    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    /** An object's mass and friction when the file gives none. */
    static final double DEFAULT_MASS_KG = 1;
    static final double DEFAULT_FRICTION = 0.5;
    /** An object's height when the file gives none, m. */
    static final double DEFAULT_HEIGHT_M = 0.1;

    private SceneryReader() {
    }

    /** A colour attribute: {@code otherwise} when absent; {@code otherwise} again, its fault recorded, when not a colour. */
    static int colour(FileFaults faults, FileElement element, String el, String text, int otherwise) {
        if (text == null) {
            return otherwise;
        }
        try {
            return Colours.parse(text);
        } catch (IllegalArgumentException e) {
            faults.add(element.at, el + " colour " + e.getMessage());
            return otherwise;
        }
    }

    /** The floor, or the plain one without {@code <floor>}; {@code folder} is where the file's image paths start. */
    static Floor floor(FileFaults faults, EnvironmentFile xml, Path folder) {
        EnvironmentFile.FloorXml f = xml.floor;
        if (f == null) {
            return Floor.PLAIN;
        }
        int base = colour(faults, f, "<floor>", f.colour, Floor.PLAIN.rgb());
        Floor.Image image = f.image == null ? null : image(faults, f, folder);
        List<Floor.Region> regions = new ArrayList<>();
        for (FileElement e : f.regions) {
            Floor.Region r = region(faults, e);
            if (r != null) {
                regions.add(r);
            }
        }
        if (regions.size() > Limits.MAX_FLOOR_REGIONS) {
            faults.add(f.at, "<floor> has " + regions.size() + " regions, at most " + Limits.MAX_FLOOR_REGIONS);
        }
        return new Floor(base, regions, image);
    }

    private static Floor.Region region(FileFaults faults, FileElement e) {
        try {
            if (e instanceof EnvironmentFile.RectangleXml r) {
                String el = "<floor> <rectangle>";
                noneOf(faults, r, el, r.name, r.taggable);
                Double x = ObstacleReader.required(faults, r, el, "x", r.x);
                Double y = ObstacleReader.required(faults, r, el, "y", r.y);
                Double w = ObstacleReader.required(faults, r, el, "width", r.width);
                Double h = ObstacleReader.required(faults, r, el, "height", r.height);
                int rgb = painted(faults, r, el, r.colour);
                if (x == null || y == null || w == null || h == null || rgb < 0) {
                    return null;
                }
                return new Floor.Region(new Floor.Rectangle(x * MM_PER_M, y * MM_PER_M, w * MM_PER_M, h * MM_PER_M),
                        rgb);
            }
            if (e instanceof EnvironmentFile.CircleXml c) {
                String el = "<floor> <circle>";
                Double x = ObstacleReader.required(faults, c, el, "x", c.x);
                Double y = ObstacleReader.required(faults, c, el, "y", c.y);
                Double r = ObstacleReader.required(faults, c, el, "radius", c.radius);
                int rgb = painted(faults, c, el, c.colour);
                if (x == null || y == null || r == null || rgb < 0) {
                    return null;
                }
                return new Floor.Region(new Floor.Disc(x * MM_PER_M, y * MM_PER_M, r * MM_PER_M), rgb);
            }
            EnvironmentFile.PolygonXml p = (EnvironmentFile.PolygonXml) e;
            String el = "<floor> <polygon>";
            noneOf(faults, p, el, p.name, p.taggable);
            double[] xy = ObstacleReader.points(faults, p, el);
            int rgb = painted(faults, p, el, p.colour);
            return xy == null || rgb < 0 ? null : new Floor.Region(new Floor.Polygon(xy), rgb);
        } catch (IllegalArgumentException bad) { // (a size that is not > 0)
            faults.add(e.at, "<floor> region " + bad.getMessage());
            return null;
        }
    }

    /** A region's colour, which it must have; -1, its fault recorded, when it has none or not a colour. */
    private static int painted(FileFaults faults, FileElement e, String el, String text) {
        if (text == null) {
            faults.add(e.at, el + " needs a colour");
            return -1;
        }
        return colour(faults, e, el, text, -1);
    }

    /** A floor region is paint, not an obstacle: it has no name and cannot be tagged. */
    private static void noneOf(FileFaults faults, FileElement e, String el, String name, Boolean taggable) {
        if (name != null || taggable != null) {
            faults.add(e.at, el + " is paint on the floor: it takes no name and no taggable (an obstacle's, in "
                    + "<obstacles>)");
        }
    }

    /** The floor's image, a PNG beside the file; null, its fault recorded, when it is none or cannot be read. */
    private static Floor.Image image(FileFaults faults, EnvironmentFile.FloorXml f, Path folder) {
        Path file = folder == null ? Path.of(f.image) : folder.resolve(f.image);
        String el = "<floor> image \"" + FileFaults.cut(f.image) + "\"";
        try {
            if (!Files.isRegularFile(file)) {
                faults.add(f.at, el + ": no such file (a path from the environment file's folder)");
                return null;
            }
            if (Files.size(file) > MAX_IMAGE_BYTES) {
                faults.add(f.at, el + ": larger than the " + MAX_IMAGE_BYTES + " bytes a floor image may have");
                return null;
            }
            byte[] bytes = Files.readAllBytes(file);
            if (bytes.length < PNG_SIGNATURE.length
                    || !java.util.Arrays.equals(bytes, 0, PNG_SIGNATURE.length, PNG_SIGNATURE, 0, PNG_SIGNATURE.length)) {
                faults.add(f.at, el + ": not a PNG image");
                return null;
            }
            javax.imageio.ImageReader reader = javax.imageio.ImageIO.getImageReadersByFormatName("png").next();
            try (javax.imageio.stream.ImageInputStream in = javax.imageio.ImageIO.createImageInputStream(
                    new java.io.ByteArrayInputStream(bytes))) {
                reader.setInput(in);
                int w = reader.getWidth(0);
                int h = reader.getHeight(0);
                if ((long) w * h > Limits.MAX_FLOOR_PIXELS) {
                    faults.add(f.at, el + ": " + w + " x " + h + " pixels, more than the " + Limits.MAX_FLOOR_PIXELS
                            + " a floor image may have");
                    return null;
                }
                java.awt.image.BufferedImage img = reader.read(0);
                int[] rgb = img.getRGB(0, 0, w, h, null, 0, w);
                return new Floor.Image(w, h, rgb);
            } finally {
                reader.dispose();
            }
        } catch (IOException | RuntimeException e) {
            faults.add(f.at, el + ": cannot be read (" + FileFaults.cut(String.valueOf(e.getMessage())) + ")");
            return null;
        }
    }

    /** The lights that have no fault, mm. */
    static List<Light> lights(FileFaults faults, EnvironmentFile xml) {
        List<Light> out = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (int i = 0; i < xml.lights.size(); i++) {
            EnvironmentFile.LightXml l = xml.lights.get(i);
            String name = l.name == null || l.name.isBlank() ? "light" + (i + 1) : l.name;
            String el = "<light name=\"" + FileFaults.cut(name) + "\">";
            if (!names.add(name)) {
                faults.add(l.at, el + " the name is used twice");
            }
            Double x = ObstacleReader.required(faults, l, el, "x", l.x);
            Double y = ObstacleReader.required(faults, l, el, "y", l.y);
            double height = l.height == null ? 0 : l.height;
            if (!(height >= 0) || Double.isInfinite(height)) {
                faults.add(l.at, el + " height must be >= 0 m (a light cannot be below the floor), got " + l.height);
                continue;
            }
            double intensity = l.intensity == null ? 1 : l.intensity;
            if (!(intensity >= 0) || Double.isInfinite(intensity)) {
                faults.add(l.at, el + " intensity must be >= 0, got " + l.intensity);
                continue;
            }
            int rgb = colour(faults, l, el, l.colour, Colours.YELLOW);
            if (x != null && y != null) {
                out.add(new Light(name, x * MM_PER_M, y * MM_PER_M, height * MM_PER_M, rgb, intensity,
                        l.on == null || l.on));
            }
        }
        if (out.size() > Limits.MAX_LIGHTS) {
            faults.add(null, "<lights> holds " + out.size() + " lights, at most " + Limits.MAX_LIGHTS);
        }
        return out;
    }

    /**
     * The objects the file places that have no fault, each checked where it stands against {@code placed} and then
     * added to it; {@code names} are the names taken so far (objects', obstacles').
     */
    static List<WorldObject> objects(FileFaults faults, EnvironmentFile xml, Placement placed, Set<String> names) {
        List<WorldObject> out = new ArrayList<>();
        for (int i = 0; i < xml.objects.all.size(); i++) {
            EnvironmentFile.ObjectXml o = xml.objects.all.get(i);
            String name = o.name == null || o.name.isBlank() ? "object" + (i + 1) : o.name;
            String el = element(o, name);
            if (!names.add(name)) {
                faults.add(o.at, el + " the name is used twice (objects and obstacles share names)");
            }
            WorldObject object = object(faults, o, el, name);
            if (object == null) {
                continue;
            }
            Double x = ObstacleReader.required(faults, o, el, "x", o.x);
            Double y = ObstacleReader.required(faults, o, el, "y", o.y);
            if (x == null || y == null) {
                continue;
            }
            object = object.at(x * MM_PER_M, y * MM_PER_M, object.headingDeg());
            if (place(faults, o, el, object, placed)) {
                out.add(object);
            }
        }
        return out;
    }

    /** How a fault names an object element. */
    static String element(EnvironmentFile.ObjectXml o, String name) {
        return "<" + (o instanceof EnvironmentFile.BoxXml ? "box" : "cylinder") + " name=\"" + FileFaults.cut(name)
                + "\">";
    }

    /** Records where {@code object} overlaps what was placed before it; else places it. True if placed. */
    static boolean place(FileFaults faults, FileElement e, String el, WorldObject object, Placement placed) {
        String over = placed.overlapOf(object);
        if (over != null) {
            faults.add(e.at, el + " at (" + object.xMm() / MM_PER_M + ", " + object.yMm() / MM_PER_M + ") m overlaps "
                    + over);
            return false;
        }
        placed.addObject(object);
        return true;
    }

    /**
     * The object {@code o} describes ({@code el} in a fault), at the origin, heading as given (its place is the
     * caller's); null, its faults recorded, when its size, mass or friction is at fault.
     */
    static WorldObject object(FileFaults faults, EnvironmentFile.ObjectXml o, String el, String name) {
        double heading = o.heading == null ? 0 : o.heading;
        if (!Double.isFinite(heading)) {
            faults.add(o.at, el + " heading must be a finite number");
            return null;
        }
        double heightM = o.height == null ? DEFAULT_HEIGHT_M : o.height;
        double mass = o.mass == null ? DEFAULT_MASS_KG : o.mass;
        double friction = o.friction == null ? DEFAULT_FRICTION : o.friction;
        boolean movable = Boolean.TRUE.equals(o.movable);
        boolean gripable = Boolean.TRUE.equals(o.gripable);
        int rgb = colour(faults, o, el, o.colour, Colours.GRAY50);
        Double width;
        Double depth;
        WorldObject.Shape shape;
        if (o instanceof EnvironmentFile.BoxXml b) {
            shape = WorldObject.Shape.BOX;
            width = ObstacleReader.required(faults, b, el, "width", b.width);
            depth = ObstacleReader.required(faults, b, el, "depth", b.depth);
        } else {
            EnvironmentFile.CylinderXml c = (EnvironmentFile.CylinderXml) o;
            shape = WorldObject.Shape.CYLINDER;
            Double r = ObstacleReader.required(faults, c, el, "radius", c.radius);
            width = r == null ? null : 2 * r;
            depth = width;
        }
        if (width == null || depth == null) {
            return null;
        }
        if (gripable && !movable) {
            faults.add(o.at, el + " is gripable, so it must be movable=\"true\" too");
            return null;
        }
        try {
            return new WorldObject(name, shape, width * MM_PER_M, depth * MM_PER_M, heightM * MM_PER_M, mass, friction,
                    movable, gripable, rgb, 0, 0, robosim.geometry.Kinematics.turn(heading, 0));
        } catch (IllegalArgumentException e) { // (a size, mass or friction out of range: said in metres here)
            faults.add(o.at, el + " needs a size > 0 m, a mass > 0 kg and a friction >= 0, got "
                    + (shape == WorldObject.Shape.BOX ? "width " + width + ", depth " + depth : "radius " + width / 2)
                    + ", height " + heightM + ", mass " + mass + ", friction " + friction);
            return null;
        }
    }
}
