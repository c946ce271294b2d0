package robosim.hardware.link;

import java.io.IOException;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.value.ValueType;
import robosim.api.Robot;

/**
 * The robot link's calls, each one of {@link Robot}'s, under the names other languages give them; a call's
 * result is packed after the reply's {@code "ok"}. The table in hardware-sim/README.md, "The robot link", lists them.
 */
final class RobotCalls {
    private RobotCalls() {
    }

    /** Makes {@code call} with {@code args} on {@code robot} and packs its result into {@code reply}. */
    static void call(Robot robot, String call, RobotLink.Arguments args, MessageBufferPacker reply)
            throws IOException, InterruptedException {
        switch (call) {
            case "name" -> {
                args.none();
                reply.packString(robot.name());
            }
            case "step_ms" -> {
                args.none();
                reply.packLong(robot.stepMs());
            }
            case "robot_names" -> {
                args.none();
                RobotLink.strings(reply, robot.robotNames());
            }
            case "move" -> {
                double mm = args.number();
                args.none();
                reply.packDouble(robot.move(mm));
            }
            case "turn" -> {
                double deg = args.number();
                args.none();
                reply.packDouble(robot.turn(deg));
            }
            case "set_velocity" -> {
                double v = args.number();
                args.none();
                robot.setVelocity(v);
                reply.packNil();
            }
            case "velocity" -> {
                args.none();
                reply.packDouble(robot.velocity());
            }
            case "set_rot_velocity" -> {
                double v = args.number();
                args.none();
                robot.setRotVelocity(v);
                reply.packNil();
            }
            case "rot_velocity" -> {
                args.none();
                reply.packDouble(robot.rotVelocity());
            }
            case "tag" -> {
                args.none();
                text(reply, robot.tag());
            }
            case "sleep" -> {
                long ms = args.whole();
                args.none();
                robot.sleep(ms);
                reply.packNil();
            }
            case "sonar_ranges" -> {
                args.none();
                RobotLink.numbers(reply, robot.sonarRanges());
            }
            case "sonar_angles_deg" -> {
                args.none();
                RobotLink.numbers(reply, robot.sonarAnglesDeg());
            }
            case "sensor_names" -> {
                args.none();
                RobotLink.strings(reply, robot.sensorNames());
            }
            case "sensor" -> {
                String name = args.text();
                args.none();
                RobotLink.numbers(reply, robot.sensor(name));
            }
            case "pose" -> {
                args.none();
                reply.packArrayHeader(3).packDouble(robot.xMm()).packDouble(robot.yMm()).packDouble(robot.headingDeg());
            }
            case "last_contact" -> {
                args.none();
                text(reply, robot.lastContact());
            }
            case "send" -> {
                String to = args.text();
                String text = args.text();
                args.none();
                robot.send(to, text);
                reply.packNil();
            }
            case "broadcast" -> {
                String text = args.text();
                args.none();
                robot.broadcast(text);
                reply.packNil();
            }
            case "receive" -> {
                args.none();
                RobotLink.message(reply, robot.receive());
            }
            case "wait_for_message" -> {
                long ms = args.whole();
                args.none();
                RobotLink.message(reply, robot.waitForMessage(ms));
            }
            case "seed" -> {
                args.none();
                reply.packLong(robot.seed());
            }
            case "parameter" -> {
                String name = args.text();
                ValueType kind = args.peek();
                if (kind == ValueType.FLOAT || kind == ValueType.INTEGER) {
                    double fallback = args.number();
                    args.none();
                    reply.packDouble(robot.parameter(name, fallback));
                } else {
                    if (kind != null && kind != ValueType.STRING) {
                        throw args.bad("parameter: a default is a text or a number, or left out");
                    }
                    String fallback = kind == ValueType.STRING ? args.text() : null;
                    args.none();
                    text(reply, robot.parameter(name, fallback));
                }
            }
            case "report" -> {
                String name = args.text();
                double value = args.number();
                args.none();
                robot.report(name, value);
                reply.packNil();
            }
            case "set_wheel_speeds" -> {
                double left = args.number();
                double right = args.number();
                args.none();
                robot.setWheelSpeeds(left, right);
                reply.packNil();
            }
            case "step" -> {
                args.none();
                robot.step();
                reply.packNil();
            }
            case "actuator_names" -> {
                args.none();
                RobotLink.strings(reply, robot.actuatorNames());
            }
            case "actuate" -> {
                String name = args.text();
                double[] values = args.numbers();
                args.none();
                robot.actuate(name, values);
                reply.packNil();
            }
            case "led_count" -> {
                args.none();
                reply.packInt(robot.ledCount());
            }
            case "set_leds" -> {
                int rgb = args.colour();
                args.none();
                robot.setLeds(rgb);
                reply.packNil();
            }
            case "set_led" -> {
                long index = args.whole();
                int rgb = args.colour();
                args.none();
                if (index < 0 || index > Integer.MAX_VALUE) {
                    throw new IllegalArgumentException("no LED " + index);
                }
                robot.setLed((int) index, rgb);
                reply.packNil();
            }
            case "set_rab_data" -> {
                double[] bytes = args.numbers();
                args.none();
                robot.actuate("rab", bytes); // (as Robot.setRabData does)
                reply.packNil();
            }
            case "grip" -> {
                args.none();
                text(reply, robot.grip());
            }
            case "release" -> {
                args.none();
                robot.release();
                reply.packNil();
            }
            case "gripped" -> {
                args.none();
                text(reply, robot.gripped());
            }
            default -> throw args.bad("no call \"" + robosim.protocol.Printable.of(call, 40) + "\" (hardware-sim/README.md, "
                    + "\"The robot link\", lists them)");
        }
    }

    /** {@code s} as a text, or nil. */
    private static void text(MessageBufferPacker reply, String s) throws IOException {
        if (s == null) {
            reply.packNil();
        } else {
            reply.packString(s);
        }
    }
}
