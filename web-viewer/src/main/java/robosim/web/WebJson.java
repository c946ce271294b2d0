package robosim.web;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import robosim.protocol.Arena;
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
import robosim.protocol.WorldSnapshot;

/**
 * The page's feed, one JSON object per WebSocket text frame, each with a {@code type}: {@code snapshot}
 * (the world: time step, arena, obstacles as polygons, every robot's name, type, radius and sonar layout,
 * and the poses), {@code update} (a step: poses, sonar ranges, tags, departed robots, robots held for their return), {@code state}
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
        ArrayNode robots = n.putArray("robots");
        for (int i = 0; i < s.robotNames().size(); i++) {
            RobotProperties p = s.robots().get(i);
            ObjectNode r = robots.addObject();
            r.put("name", s.robotNames().get(i));
            r.put("type", p.type());
            r.put("radius", p.radiusMm());
            ArrayNode sonars = r.putArray("sonars");
            for (SonarSpec sonar : p.sonars()) {
                sonars.addObject().put("x", sonar.xMm()).put("y", sonar.yMm()).put("angle", sonar.angleDeg())
                        .put("cone", sonar.coneDeg()).put("range", sonar.maxRangeMm());
            }
        }
        n.set("poses", poses(s.poses()));
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
