import java.lang.reflect.Proxy;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import robosim.api.Robot;
import robosim.hardware.link.RobotLink;

/**
 * The floor of the robot link's shape: a controller in another process making calls one after another over the link
 * (RobotLink, on a platform thread of this JVM) to a robot that answers each at once, with no simulation behind it:
 * what one round trip costs, the least a call of a Python controller can cost. The controller is the Python package's
 * robosim.Robot (PYTHON, with python/src on its path), making CALLS calls of {@code pose}.
 * usage: java -cp 'runner/target/lib/*' bench/LinkFloor.java PYTHON CALLS
 * Prints one line: calls=N wall=Ws round_trips/s=R us/round_trip=U.
 */
public class LinkFloor {
    public static void main(String[] args) throws Exception {
        String python = args[0];
        int calls = Integer.parseInt(args[1]);
        Robot instant = (Robot) Proxy.newProxyInstance(LinkFloor.class.getClassLoader(), new Class<?>[] {Robot.class},
                (proxy, method, a) -> switch (method.getName()) {
                    case "name" -> "r1";
                    case "robotNames" -> List.of("r1");
                    case "stepMs", "seed" -> 100L;
                    case "xMm", "yMm", "headingDeg" -> 0.0;
                    default -> throw new UnsupportedOperationException(method.getName());
                });
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            String client = """
                    import sys, time
                    from robosim import Robot
                    robot = Robot.connect("127.0.0.1", int(sys.argv[1]), "r1")
                    for _ in range(1000):
                        robot.pose()
                    t0 = time.perf_counter()
                    for _ in range(int(sys.argv[2])):
                        robot.pose()
                    print(time.perf_counter() - t0)
                    robot.call("bye")
                    """;
            ProcessBuilder pb = new ProcessBuilder(python, "-c", client, Integer.toString(server.getLocalPort()),
                    Integer.toString(calls)).redirectError(ProcessBuilder.Redirect.INHERIT);
            pb.environment().put("PYTHONPATH", "python/src");
            Process p = pb.start();
            RobotLink.serve(server.accept(), instant);
            String out = new String(p.getInputStream().readAllBytes()).trim();
            if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
                throw new IllegalStateException("the controller failed: " + out);
            }
            double wall = Double.parseDouble(out);
            System.out.printf(Locale.ROOT, "calls=%d wall=%.3fs round_trips/s=%.0f us/round_trip=%.1f%n", calls, wall,
                    calls / wall, wall * 1e6 / calls);
        }
    }
}
