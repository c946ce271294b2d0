package robosim.hardware;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.api.RobotControl;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * A fake Environment for one real Hardware Simulator over a loopback socket on an ephemeral port: it
 * welcomes the robot with a given time step, grants every request in full for a number of steps, then
 * ends the simulation. The fake runs on its own thread ({@code scripted-environment}); the robot's
 * exchange on the caller's.
 */
final class ScriptedEnvironment {
    /** What the fake saw: the robot's hello, each step's request in order, and the robot's end reason. */
    record Run(RobotHello hello, List<StepRequest> requests, String endReason) {
    }

    static final String END_REASON = "scripted end";

    private ScriptedEnvironment() {
    }

    /** Runs {@code control} on an ArRobot named robot1 (robot2 also in the world) for {@code steps} steps. */
    static Run run(RobotControl control, long stepMs, int steps) throws Exception {
        List<StepRequest> seen = new ArrayList<>();
        CompletableFuture<RobotHello> hello = new CompletableFuture<>();
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            Thread environment = new Thread(() -> {
                try {
                    hello.complete(serve(server, stepMs, steps, seen));
                } catch (IOException | RuntimeException e) {
                    hello.completeExceptionally(e);
                }
            }, "scripted-environment");
            environment.start();
            HardwareSimulator sim = new HardwareSimulator("robot1", new robosim.devices.ArRobot());
            sim.connect(new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort()), 16);
            String reason = sim.run(control);
            return new Run(hello.get(10, TimeUnit.SECONDS), List.copyOf(seen), reason);
        }
    }

    private static RobotHello serve(ServerSocket server, long stepMs, int steps, List<StepRequest> seen)
            throws IOException {
        try (Socket s = server.accept(); ObjectConnection c = new ObjectConnection(s, 16)) {
            RobotHello hello = c.read(RobotHello.class);
            c.write(RobotWelcome.accepted(stepMs, 1000, 1000, 0, List.of("robot1", "robot2")));
            for (int k = 0; k < steps; k++) {
                c.writeStep(k);
                c.flush();
                StepRequest q = c.read(StepRequest.class);
                seen.add(q);
                c.write(new StepResponse(k, q.moveMm(), q.turnDeg(), "", 0, 0, 0, new double[8], List.of(),
                        List.of()));
            }
            c.writeStep(Protocol.END_OF_SIMULATION);
            c.write(new SimulationEnd(steps - 1, END_REASON));
            c.flush();
            return hello;
        }
    }
}
