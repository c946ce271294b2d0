package robosim.web;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import robosim.protocol.Arena;
import robosim.protocol.Floor;
import robosim.protocol.LedSpec;
import robosim.protocol.Light;
import robosim.protocol.ObstacleShape;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotView;
import robosim.protocol.RunState;
import robosim.devices.SensorInfo;
import robosim.devices.Sensors;
import robosim.protocol.SensorReading;
import robosim.protocol.SimulationEnd;
import robosim.protocol.SonarSpec;
import robosim.protocol.WorldObject;
import robosim.protocol.WorldSnapshot;

/**
 * The page's feed, one JSON object per WebSocket text frame, each with a {@code type}: {@code snapshot}
 * (the world: time step, arena, obstacles as polygons, the floor (its colour, painted regions and image as a PNG data
 * URL), the lights, the objects' shapes, every robot's name, type, radius, height, sonar layout and LEDs' places, and
 * the poses), {@code update} (a step: poses, sonar ranges, the objects' poses and the LEDs' colours when the world has
 * them, what its loop functions painted and whether each light is on when it has them, tags, departed robots, robots
 * held for their return), {@code state}
 * (waiting, running, paused, at a step), {@code end}, and for a page that watches a robot {@code watchStarted},
 * {@code view} (its step as it saw it: command, contact, tag, readings, each with how its sensor shows it,
 * {@code RANGES}, {@code SIDES} or {@code VALUES} from {@code robosim.devices.Sensors#display}, messages sent and
 * delivered, notices) and {@code viewEnded}. Lengths in mm and angles in degrees, as on the wire.
 */
final class WebJson {
    private static final ObjectMapper JSON = new ObjectMapper();

    private WebJson() {
    }

    static String snapshot(WorldSnapshot s) {
        ObjectNode n = JSON.createObjectNode();
        n.put("type", "snapshot");
        n.put("step", s.step());
        n.put("timeStepMs", s.timeStepMs());
        Arena a = s.arena();
        ObjectNode arena = n.putObject("arena");
        arena.put("minX", a.minXMm()).put("minY", a.minYMm()).put("maxX", a.maxXMm()).put("maxY", a.maxYMm());
        ArrayNode obstacles = n.putArray("obstacles");
        for (ObstacleShape o : s.obstacles()) {
            ObjectNode on = obstacles.addObject();
            on.put("name", o.name());
            ArrayNode xy = on.putArray("xy");
            for (double v : o.xyMm()) {
                xy.add(v);
            }
        }
        floor(n.putObject("floor"), s.scenery().floor());
        ArrayNode lights = n.putArray("lights");
        for (Light l : s.scenery().lights()) {
            lights.addObject().put("name", l.name()).put("x", l.xMm()).put("y", l.yMm()).put("height", l.heightMm())
                    .put("colour", colour(l.rgb())).put("intensity", l.intensity()).put("on", l.on());
        }
        ArrayNode objects = n.putArray("objects");
        for (WorldObject o : s.scenery().objects()) {
            objects.addObject().put("name", o.name()).put("shape", o.shape().name().toLowerCase(java.util.Locale.ROOT))
                    .put("width", o.widthMm()).put("depth", o.depthMm()).put("height", o.heightMm())
                    .put("movable", o.movable()).put("colour", colour(o.rgb())).put("x", o.xMm()).put("y", o.yMm())
                    .put("heading", o.headingDeg());
        }
        ArrayNode robots = n.putArray("robots");
        for (int i = 0; i < s.robotNames().size(); i++) {
            RobotProperties p = s.robots().get(i);
            ObjectNode r = robots.addObject();
            r.put("name", s.robotNames().get(i));
            r.put("type", p.type());
            r.put("radius", p.radiusMm());
            r.put("height", p.heightMm());
            ArrayNode leds = r.putArray("leds");
            for (LedSpec l : p.leds()) {
                leds.addArray().add(l.xMm()).add(l.yMm()).add(l.zMm());
            }
            ArrayNode sonars = r.putArray("sonars");
            for (SonarSpec sonar : p.sonars()) {
                sonars.addObject().put("x", sonar.xMm()).put("y", sonar.yMm()).put("angle", sonar.angleDeg())
                        .put("cone", sonar.coneDeg()).put("range", sonar.maxRangeMm());
            }
        }
        n.set("poses", poses(s.poses()));
        return n.toString();
    }

    /** A colour as a page takes it: {@code #rrggbb}. */
    private static String colour(int rgb) {
        return String.format(java.util.Locale.ROOT, "#%06x", rgb & 0xFFFFFF);
    }

    /** The floor: its colour, its regions ({@code kind} rectangle, disc or polygon) and its image as a PNG. */
    private static void floor(ObjectNode n, Floor f) {
        n.put("colour", colour(f.rgb()));
        regions(n.putArray("regions"), f.regions());
        Floor.Image image = f.image();
        if (image == null) {
            n.putNull("image");
            return;
        }
        java.awt.image.BufferedImage b = new java.awt.image.BufferedImage(image.width(), image.height(),
                java.awt.image.BufferedImage.TYPE_INT_RGB);
        b.setRGB(0, 0, image.width(), image.height(), image.rgb(), 0, image.width());
        java.io.ByteArrayOutputStream png = new java.io.ByteArrayOutputStream();
        try {
            javax.imageio.ImageIO.write(b, "png", png);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e); // (into memory: not expected)
        }
        n.put("image", "data:image/png;base64," + java.util.Base64.getEncoder().encodeToString(png.toByteArray()));
    }

    /** Painted regions, each its colour and {@code kind} (rectangle, disc or polygon) with its place. */
    private static void regions(ArrayNode regions, java.util.List<Floor.Region> all) {
        for (Floor.Region r : all) {
            ObjectNode region = regions.addObject().put("colour", colour(r.rgb()));
            if (r.area() instanceof Floor.Rectangle a) {
                region.put("kind", "rectangle").put("x", a.xMm()).put("y", a.yMm()).put("width", a.widthMm())
                        .put("height", a.heightMm());
            } else if (r.area() instanceof Floor.Disc a) {
                region.put("kind", "disc").put("x", a.xMm()).put("y", a.yMm()).put("radius", a.radiusMm());
            } else {
                ArrayNode xy = region.put("kind", "polygon").putArray("xy");
                for (double v : ((Floor.Polygon) r.area()).xyMm()) {
                    xy.add(v);
                }
            }
        }
    }

    /**
     * What the loop functions drew ({@code traces}, a piece of their drawing or the whole): {@code {"type": "traces",
     * "fresh", "firstTrace", "names", "colours", "firstPoint", "points": [TRACE, X, Y, ...]}} (mm).
     */
    static String traces(robosim.protocol.Traces piece) {
        ObjectNode n = JSON.createObjectNode();
        n.put("type", "traces");
        n.put("fresh", piece.fresh());
        n.put("firstTrace", piece.firstTrace());
        ArrayNode names = n.putArray("names");
        ArrayNode colours = n.putArray("colours");
        for (int t = piece.firstTrace(); t < piece.firstTrace() + piece.traces(); t++) {
            names.add(piece.name(t));
            colours.add(colour(piece.rgb(t)));
        }
        n.put("firstPoint", piece.firstPoint());
        ArrayNode points = n.putArray("points");
        for (int p = piece.firstPoint(); p < piece.firstPoint() + piece.points(); p++) {
            points.add(piece.traceOf(p));
            points.add(Math.round(piece.xMm(p) * 10) / 10.0); // (a tenth of a millimetre is plenty on a screen)
            points.add(Math.round(piece.yMm(p) * 10) / 10.0);
        }
        return n.toString();
    }

    static String update(PoseUpdate u) {
        return poses(u).toString();
    }

    private static ObjectNode poses(PoseUpdate u) {
        ObjectNode n = JSON.createObjectNode();
        n.put("type", "update");
        n.put("step", u.step());
        ArrayNode x = n.putArray("x");
        ArrayNode y = n.putArray("y");
        ArrayNode h = n.putArray("heading");
        ArrayNode sonar = n.putArray("sonar");
        for (int i = 0; i < u.count(); i++) {
            x.add(u.xMm(i));
            y.add(u.yMm(i));
            h.add(u.headingDeg(i));
            ArrayNode ranges = sonar.addArray();
            for (double r : u.sonarMm(i)) {
                ranges.add(Math.round(r)); // (a millimetre is plenty on a screen)
            }
        }
        if (u.objectCount() > 0) {
            ObjectNode objects = n.putObject("objects");
            ArrayNode ox = objects.putArray("x");
            ArrayNode oy = objects.putArray("y");
            ArrayNode oh = objects.putArray("heading");
            for (int o = 0; o < u.objectCount(); o++) {
                ox.add(u.objectXMm(o));
                oy.add(u.objectYMm(o));
                oh.add(u.objectHeadingDeg(o));
            }
            ArrayNode gone = objects.putArray("gone"); // (out of the world: the loop functions took them out)
            for (int o : u.objectsGone()) {
                gone.add(o);
            }
        }
        ArrayNode leds = null;
        for (int i = 0; i < u.count(); i++) {
            if (u.leds(i).length > 0 && leds == null) {
                leds = n.putArray("leds");
                for (int before = 0; before < i; before++) {
                    leds.addArray();
                }
            }
            if (leds != null) {
                ArrayNode robot = leds.addArray();
                for (int c : u.leds(i)) {
                    robot.add(colour(c));
                }
            }
        }
        boolean[] on = u.lightsOn();
        if (on != null) { // (a world with loop functions: what they painted, and the lights as they switched them)
            regions(n.putArray("paint"), u.paint());
            ArrayNode lights = n.putArray("lightsOn");
            for (boolean b : on) {
                lights.add(b);
            }
        }
        ArrayNode tags = n.putArray("tags");
        u.tags().forEach(tags::add);
        ArrayNode departed = n.putArray("departed");
        u.departed().forEach(departed::add);
        ArrayNode held = n.putArray("held");
        u.held().forEach(held::add);
        return n;
    }

    /** Robot {@code name}'s view of a step (the page's robot panel); readings to the tenth, as drawn. */
    static String view(String name, RobotView v) {
        ObjectNode n = JSON.createObjectNode();
        n.put("type", "view");
        n.put("name", name);
        n.put("step", v.step());
        n.put("since", v.sinceStep());
        n.put("leftOut", v.leftOut());
        n.put("move", v.moveMm()).put("turn", v.turnDeg()).put("sonar", v.askedSonar()).put("tag", v.askedTag());
        n.put("contact", v.contact()).put("tagged", v.tagged());
        ArrayNode readings = n.putArray("readings");
        for (SensorReading r : v.readings()) {
            SensorInfo.Display display = Sensors.display(r.name(), r.values().length);
            ObjectNode reading = readings.addObject().put("name", r.name()).put("display", display.name());
            if (display == SensorInfo.Display.SIDES) {
                SensorInfo.Display.SIDES_NAMED.forEach(reading.putArray("sides")::add);
            }
            ArrayNode values = reading.putArray("values");
            for (double d : r.values()) {
                values.add(Math.round(d * 10) / 10.0);
            }
        }
        ArrayNode sent = n.putArray("sent");
        v.sent().forEach(m -> sent.addObject().put("to", m.to()).put("text", m.payload()));
        ArrayNode delivered = n.putArray("delivered");
        v.delivered().forEach(m -> delivered.addObject().put("from", m.from()).put("text", m.payload()));
        ArrayNode notices = n.putArray("notices");
        v.notices().forEach(notices::add);
        return n.toString();
    }

    /** A page's watch of a robot has begun: its views from the step after {@code step} on. */
    static String watchStarted(String name, long step) {
        return JSON.createObjectNode().put("type", "watchStarted").put("name", name).put("step", step).toString();
    }

    /** The page's watch of a robot has ended ({@code reason}: why, e.g. a refusal). */
    static String viewEnded(String name, String reason) {
        ObjectNode n = JSON.createObjectNode();
        n.put("type", "viewEnded");
        n.put("name", name);
        n.put("reason", reason);
        return n.toString();
    }

    /** A reply to a page's request: done. */
    static String ok(String message) {
        return JSON.createObjectNode().put("ok", true).put("message", message).toString();
    }

    /** A reply to a page's request: refused, and why. */
    static String refusal(String error) {
        return JSON.createObjectNode().put("ok", false).put("error", error).toString();
    }

    static String state(RunState s) {
        ObjectNode n = JSON.createObjectNode();
        n.put("type", "state");
        n.put("phase", s.phase().name());
        n.put("step", s.step());
        return n.toString();
    }

    static String end(SimulationEnd e) {
        ObjectNode n = JSON.createObjectNode();
        n.put("type", "end");
        n.put("step", e.lastStep());
        n.put("reason", e.reason());
        return n.toString();
    }
}
