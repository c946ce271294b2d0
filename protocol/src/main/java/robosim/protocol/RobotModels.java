package robosim.protocol;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The robot types every RoboSim process knows by name, with their default properties. An
 * environment file names one of these per robot; the Hardware Simulator sends the properties in its
 * handshake, and the Environment refuses a robot whose type differs from the file's.
 *
 * <ul>
 * <li>{@code ArRobot}: Pioneer-like, radius 250 mm, 8 front sonars at 90, 50, 30, 10, -10, -30,
 * -50, -90 degrees (15 degree cones, 5 m).</li>
 * <li>{@code Scout}: radius 190 mm, 16 sonars all round every 22.5 degrees (22.5 degree cones, 5 m).</li>
 * </ul>
 */
public final class RobotModels {
    public static final RobotProperties AR_ROBOT = arRobot();
    public static final RobotProperties SCOUT = scout();
    private static final Map<String, RobotProperties> KNOWN = known();

    private RobotModels() {
    }

    private static RobotProperties arRobot() {
        double r = 250;
        List<SonarSpec> sonars = new ArrayList<>();
        for (double a : new double[] {90, 50, 30, 10, -10, -30, -50, -90}) {
            sonars.add(SonarSpec.onRim(r, a, 15, 5000));
        }
        return new RobotProperties("ArRobot", r, 1000, 300, sonars);
    }

    private static RobotProperties scout() {
        double r = 190;
        List<SonarSpec> sonars = new ArrayList<>();
        for (int i = 0; i < 16; i++) {
            sonars.add(SonarSpec.onRim(r, i * 22.5, 22.5, 5000));
        }
        return new RobotProperties("Scout", r, 1000, 300, sonars);
    }

    private static Map<String, RobotProperties> known() {
        Map<String, RobotProperties> m = new LinkedHashMap<>();
        m.put(AR_ROBOT.type(), AR_ROBOT);
        m.put(SCOUT.type(), SCOUT);
        return Map.copyOf(m);
    }

    /** The default properties of a known type, or null. */
    public static RobotProperties byName(String type) {
        return KNOWN.get(type);
    }

    public static Set<String> names() {
        return new java.util.TreeSet<>(KNOWN.keySet());
    }
}
