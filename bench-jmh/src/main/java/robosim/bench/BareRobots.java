package robosim.bench;

import java.io.EOFException;
import java.io.Externalizable;
import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.util.List;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.StepRequest;

/**
 * The floors' client side speaking RoboSim's robot protocol: one thread owns every robot's socket and,
 * each step, sends every robot its request (drive 20 mm, turn 3 degrees, read the 16 sonars) in world
 * order, then reads every response. No control code, no control threads: set against a floor, it
 * measures the Environment (and the Geometry process) alone, without the robots' process.
 * Usage: {@code BareRobots PORT N [still]} for robots {@code b1..bN} of {@code test-envs/bench-N.xml}
 * (Scouts), with the Environment's default reset interval and step messages on; {@code still}: every
 * request asks for nothing (no move, no sonar), which leaves the coordination alone. Prints
 * {@code steps=S wall=Ws} (first step to the end) like the floors.
 */
public final class BareRobots {
    private BareRobots() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 2 || args.length > 3 || (args.length == 3 && !args[2].equals("still"))) {
            System.err.println("usage: BareRobots PORT N [still] (robots b1..bN of test-envs/bench-N.xml on 127.0.0.1:PORT)");
            System.exit(2);
        }
        int port = Integer.parseInt(args[0]);
        int n = Integer.parseInt(args[1]);
        boolean still = args.length == 3;
        ObjectConnection[] robots = new ObjectConnection[n];
        for (int i = 0; i < n; i++) {
            robots[i] = new ObjectConnection(new Socket(InetAddress.getLoopbackAddress(), port), 256);
            robots[i].write(new RobotHello("b" + (i + 1), robosim.devices.RobotTypes.properties("Scout")));
            robots[i].flush();
            RobotWelcome welcome = robots[i].read(RobotWelcome.class);
            if (!welcome.isAccepted()) {
                throw new IOException("robot b" + (i + 1) + " refused: " + welcome.reason());
            }
        }
        long[] next = new long[n];
        for (int i = 0; i < n; i++) {
            next[i] = robots[i].readStep();
        }
        long start = System.nanoTime();
        long steps = 0;
        while (true) {
            for (int i = 0; i < n; i++) {
                robots[i].write(still ? new StepRequest(next[i], 0, 0, false, List.of())
                        : new StepRequest(next[i], 20, 3, true, List.of()));
                robots[i].flush();
            }
            boolean over = false;
            for (int i = 0; i < n; i++) {
                Externalizable answer;
                try {
                    answer = robots[i].read(Externalizable.class);
                    next[i] = robots[i].readStep();
                } catch (EOFException e) {
                    over = true;
                    continue;
                }
                over |= !(answer instanceof robosim.protocol.StepResponse) || next[i] == Protocol.END_OF_SIMULATION;
            }
            steps++;
            if (over) {
                break;
            }
        }
        double wall = (System.nanoTime() - start) / 1e9;
        System.out.printf("steps=%d wall=%.3fs%n", steps, wall);
        for (ObjectConnection r : robots) {
            r.close();
        }
    }
}
