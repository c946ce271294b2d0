package robosim.runner;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.devices.ActuatorInfo;
import robosim.devices.Actuators;
import robosim.devices.Attribute;
import robosim.devices.RobotType;
import robosim.devices.RobotTypes;
import robosim.devices.SensorInfo;
import robosim.devices.Sensors;
import robosim.environment.metrics.MetricInfo;
import robosim.environment.metrics.Metrics;
import robosim.protocol.CommandLines;
import robosim.protocol.SonarSpec;

/**
 * {@code scripts/describe.sh [WHAT]}: what RoboSim knows, read from its registries, as {@code argos3 -q} does from
 * ARGoS's: the sensors ({@link Sensors}), the actuators ({@link Actuators}), the robot types ({@link RobotTypes}) and
 * the built-in metrics ({@link Metrics}), a line each, or one of them in full by its name; with {@code --markdown}, a list as the READMEs'
 * tables (a test holds each README's table to it). Exit codes: 0, 2 for a name nothing has.
 */
@Command(name = "describe.sh", mixinStandardHelpOptions = true,
        description = "Says what RoboSim knows, from its registries: the sensors, the actuators, the robot types and "
                + "the built-in metrics, a line each, or one of them in full (its attributes, values, devices or "
                + "unit).")
public final class DescribeMain implements Callable<Integer> {
    /** What may be listed. */
    static final List<String> LISTS = List.of("sensors", "actuators", "robots", "metrics");

    @Parameters(index = "0", arity = "0..1", paramLabel = "WHAT", description = "sensors, actuators, robots or metrics "
            + "(a line each), or the name of a sensor, an actuator, a robot type or a metric (in full); default: all "
            + "four lists.")
    String what;

    @Option(names = "--markdown", description = "A list as a Markdown table (as the READMEs hold it).")
    boolean markdown;

    @Override
    public Integer call() {
        if (what == null) {
            for (String list : LISTS) {
                System.out.println(list + ":");
                list(list).forEach(l -> System.out.println("  " + l));
            }
            return 0;
        }
        if (LISTS.contains(what)) {
            (markdown ? table(what) : list(what)).forEach(System.out::println);
            return 0;
        }
        List<String> one = one(what);
        if (one == null) {
            System.err.println("describe: nothing is named '" + robosim.protocol.Printable.of(what, 64)
                    + "' (sensors: " + String.join(", ", Sensors.all().stream().map(SensorInfo::name).toList())
                    + "; actuators: " + String.join(", ", Actuators.all().stream().map(ActuatorInfo::name).toList())
                    + "; robot types: " + String.join(", ", RobotTypes.names()) + "; metrics: "
                    + String.join(", ", Metrics.names()) + ")");
            return 2;
        }
        one.forEach(System.out::println);
        return 0;
    }

    /** A line each of {@code list}'s members. */
    static List<String> list(String list) {
        List<String> out = new ArrayList<>();
        switch (list) {
            case "sensors" -> Sensors.all().forEach(s -> out.add(String.format(Locale.ROOT, "%-10s %s%s", s.name(),
                    s.summary(), s.geometry() ? " (the Geometry process's)" : "")));
            case "actuators" -> Actuators.all().forEach(a -> out.add(String.format(Locale.ROOT, "%-10s %s", a.name(),
                    a.summary())));
            case "robots" -> RobotTypes.all().forEach(t -> out.add(String.format(Locale.ROOT, "%-10s %s", t.name(),
                    t.summary())));
            default -> Metrics.builtIn().forEach(m -> out.add(String.format(Locale.ROOT, "%-20s %s (%s)", m.name(),
                    m.description(), m.unit())));
        }
        return out;
    }

    /** {@code list} as a Markdown table. */
    static List<String> table(String list) {
        List<String> out = new ArrayList<>();
        switch (list) {
            case "sensors" -> {
                out.add("| sensor | what it senses | attributes: default, range | values | computed by |");
                out.add("|---|---|---|---|---|");
                for (SensorInfo s : Sensors.all()) {
                    out.add("| `" + s.name() + "` | " + s.summary() + " | " + attributes(s.attributes()) + " | "
                            + s.values() + " | " + (s.geometry() ? "the Geometry process" : "the Environment") + " |");
                }
            }
            case "actuators" -> {
                out.add("| actuator | what it does | attributes: default, range | values |");
                out.add("|---|---|---|---|");
                for (ActuatorInfo a : Actuators.all()) {
                    out.add("| `" + a.name() + "` | " + a.summary() + " | " + attributes(a.attributes()) + " | "
                            + a.values() + " |");
                }
            }
            case "robots" -> {
                out.add("| type | what it is | radius, height, mass, wheel base | speed limits | sonars: angles (deg), "
                        + "cone, range | devices |");
                out.add("|---|---|---|---|---|---|");
                for (RobotType t : RobotTypes.all()) {
                    out.add("| `" + t.name() + "` | " + t.summary() + " | " + body(t) + " | "
                            + Attribute.plain(round(t.body().maxSpeedMmPerS())) + " mm/s, "
                            + Attribute.plain(round(t.body().maxTurnDegPerS())) + " deg/s | " + sonars(t) + " | "
                            + devices(t) + " |");
                }
            }
            default -> {
                out.add("| metric | unit | interval of its mean | what |");
                out.add("|---|---|---|---|");
                for (MetricInfo m : Metrics.builtIn()) {
                    out.add("| `" + m.name() + "` | " + m.unit() + " | " + (m.interval() == MetricInfo.Interval.BOOTSTRAP
                            ? "bootstrap" : "Student's t") + " | " + m.description() + " |");
                }
            }
        }
        return out;
    }

    /** Attributes as a table's cell says them: name, default, range; "none". */
    private static String attributes(List<Attribute> attributes) {
        return attributes.isEmpty() ? "none" : String.join("; ", attributes.stream()
                .map(a -> "`" + a.name() + "` " + a.shownDefault() + ", " + a.range()).toList());
    }

    /** A number to the tenth, as a line shows a measure. */
    private static double round(double v) {
        return Math.round(v * 10) / 10.0;
    }

    private static String body(RobotType t) {
        return Attribute.plain(round(t.body().radiusMm())) + " mm, " + Attribute.plain(round(t.body().heightMm()))
                + " mm, " + Attribute.plain(t.body().massKg()) + " kg, " + Attribute.plain(round(t.body().wheelBaseMm()))
                + " mm";
    }

    /** A type's devices besides its sonar: each name and kind, its LEDs, its proximity rays, its gripper. */
    private static String devices(RobotType t) {
        List<String> d = new ArrayList<>();
        for (robosim.devices.DeviceSpec s : t.devices()) {
            d.add("`" + s.name() + "` (" + (s.actuator() ? "actuator" : "sensor")
                    + (s.attributes().containsKey("model") ? ", " + s.attributes().get("model") : "") + ")");
        }
        robosim.protocol.RobotProperties p = t.properties();
        if (!p.rays().isEmpty()) {
            d.add(p.rays().size() + " proximity rays of " + Attribute.plain(p.rays().get(0).rangeMm()) + " mm");
        }
        if (!p.leds().isEmpty()) {
            d.add(p.leds().size() == 1 ? "1 LED" : p.leds().size() + " LEDs");
        }
        if (p.gripper() != null) {
            d.add("a gripper (" + Attribute.plain(p.gripper().reachMm()) + " mm, "
                    + Attribute.plain(p.gripper().halfAngleDeg()) + " deg either side)");
        }
        return d.isEmpty() ? "none" : String.join(", ", d);
    }

    private static String sonars(RobotType t) {
        if (t.sonars().isEmpty()) {
            return "none";
        }
        SonarSpec first = t.sonars().get(0);
        return t.sonars().size() + ": " + String.join(", ", t.sonars().stream().map(s -> Attribute.plain(s.angleDeg()))
                .toList()) + "; " + Attribute.plain(first.coneDeg()) + " deg, " + Attribute.plain(first.maxRangeMm())
                + " mm";
    }

    /** The sensor, robot type or metric named {@code name}, in full; null if nothing has the name. */
    static List<String> one(String name) {
        SensorInfo s = Sensors.info(name);
        if (s != null) {
            List<String> out = new ArrayList<>(List.of("sensor " + s.name() + ": " + s.summary(),
                    "computed by: " + (s.geometry() ? "the Geometry process (it comes with the robot's type)"
                            : "the Environment (<sensor type=\"" + s.name() + "\"/> in a <robot>)"),
                    "values: " + s.values() + (s.unit().isEmpty() ? "" : " (" + s.unit() + ")"), "attributes:"));
            if (s.attributes().isEmpty()) {
                out.add("  none");
            }
            for (Attribute a : s.attributes()) {
                out.add("  " + a.name() + " (default " + a.shownDefault() + ", " + a.range() + "): " + a.description());
            }
            return out;
        }
        ActuatorInfo act = Actuators.info(name);
        if (act != null) {
            List<String> out = new ArrayList<>(List.of("actuator " + act.name() + ": " + act.summary(),
                    "values: " + act.values(), "attributes:"));
            if (act.attributes().isEmpty()) {
                out.add("  none");
            }
            for (Attribute a : act.attributes()) {
                out.add("  " + a.name() + " (default " + a.shownDefault() + ", " + a.range() + "): " + a.description());
            }
            return out;
        }
        RobotType t = RobotTypes.known(name);
        if (t != null) {
            return List.of("robot type " + t.name() + ": " + t.summary(),
                    "body: radius, height, mass, wheel base " + body(t) + "; at most "
                            + Attribute.plain(round(t.body().maxSpeedMmPerS())) + " mm/s and "
                            + Attribute.plain(round(t.body().maxTurnDegPerS())) + " deg/s; move starts at "
                            + Attribute.plain(t.body().velocityMmPerS()) + " mm/s, turn at "
                            + Attribute.plain(t.body().rotVelocityDegPerS()) + " deg/s",
                    "sonars: " + sonars(t), "devices: " + devices(t));
        }
        MetricInfo m = Metrics.info(name);
        if (m != null) {
            return List.of("metric " + m.name() + ": " + m.description(), "unit: " + m.unit(),
                    "interval of its mean in summary.csv: " + (m.interval() == MetricInfo.Interval.BOOTSTRAP
                            ? "bootstrap percentile" : "Student's t"));
        }
        return null;
    }

    public static void main(String[] args) {
        CommandLines.exit("describe", new DescribeMain(), args);
    }
}
