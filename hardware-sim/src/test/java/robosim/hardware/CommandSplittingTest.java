package robosim.hardware;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.api.RobotControl;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/** The splitting rule: step 500 ms, 500 mm/s: move(750) is exactly three steps of 250 mm. */
class CommandSplittingTest {
    private static StepResponse moved(double mm, double deg) {
        return new StepResponse(0, mm, deg, "", 0, 0, 0, new double[0], List.of(), List.of());
    }

    @Test
    void move750TakesThreeStepsOf250() {
        Command c = Command.move(750, 500);
        List<Double> pieces = new ArrayList<>();
        boolean done = false;
        while (!done) {
            c.plan(0.5);
            pieces.add(c.plannedMoveMm);
            done = c.apply(moved(c.plannedMoveMm, 0), false);
        }
        assertEquals(List.of(250.0, 250.0, 250.0), pieces);
        assertEquals(750, c.result);
    }

    @Test
    void aShortLastPieceAndBackwardsMoves() {
        Command c = Command.move(-600, 500);
        List<Double> pieces = new ArrayList<>();
        boolean done = false;
        while (!done) {
            c.plan(0.5);
            pieces.add(c.plannedMoveMm);
            done = c.apply(moved(c.plannedMoveMm, 0), false);
        }
        assertEquals(List.of(-250.0, -250.0, -100.0), pieces);
    }

    @Test
    void aBlockedMoveEndsAtOnceWithTheDistanceCovered() {
        Command c = Command.move(1000, 500);
        c.plan(0.5);
        assertFalse(c.apply(moved(250, 0), false));
        c.plan(0.5);
        assertTrue(c.apply(moved(40, 0), false), "touching something ends the move");
        assertEquals(290, c.result);
    }

    @Test
    void turn180At90DegPerSecondTakesFourSteps() {
        Command c = Command.turn(180, 90);
        int steps = 0;
        boolean done = false;
        while (!done) {
            c.plan(0.5);
            assertEquals(45, c.plannedTurnDeg);
            done = c.apply(moved(0, c.plannedTurnDeg), false);
            steps++;
        }
        assertEquals(4, steps);
    }

    /**
     * Through a real Hardware Simulator and a scripted Environment on a loopback socket: the control
     * code's move(750), turn(90), send and sleep show up as exactly these requests, step by step.
     */
    @Test
    void theHardwareSimulatorSendsOnePiecePerStepWithNoIdleStepsBetweenCalls() throws Exception {
        RobotControl control = robot -> {
            robot.move(750);
            robot.send("robot2", "hello");
            robot.turn(90);
            robot.sleep(1000);
        };
        List<StepRequest> seen = new ArrayList<>();
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            CompletableFuture<Void> env = CompletableFuture.runAsync(() -> script(server, seen, 9));
            HardwareSimulator sim = new HardwareSimulator("robot1", new ArRobot());
            sim.connect(new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort()), 16);
            assertEquals("scripted end", sim.run(control));
            env.get(10, TimeUnit.SECONDS);
        }
        double[] moves = seen.stream().mapToDouble(StepRequest::moveMm).toArray();
        double[] turns = seen.stream().mapToDouble(StepRequest::turnDeg).toArray();
        assertEquals(List.of(250.0, 250.0, 250.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), box(moves));
        assertEquals(List.of(0.0, 0.0, 0.0, 45.0, 45.0, 0.0, 0.0, 0.0, 0.0), box(turns));
        assertEquals("hello", seen.get(3).messages().get(0).payload(), "the message goes out with the next step");
        assertEquals("robot2", seen.get(3).messages().get(0).to());
        assertTrue(seen.get(0).wantsSonar());
    }

    private static List<Double> box(double[] a) {
        List<Double> l = new ArrayList<>();
        for (double v : a) {
            l.add(v);
        }
        return l;
    }

    /** A fake Environment that grants every request in full for {@code steps} steps, then ends. */
    private static void script(ServerSocket server, List<StepRequest> seen, int steps) {
        try (Socket s = server.accept(); ObjectConnection c = new ObjectConnection(s, 16)) {
            RobotHello hello = c.read(RobotHello.class);
            assertEquals("ArRobot", hello.properties().type());
            c.write(RobotWelcome.accepted(500, 1000, 1000, 0, List.of("robot1", "robot2")));
            for (int k = 0; k < steps; k++) {
                c.writeStep(k);
                c.flush();
                StepRequest q = c.read(StepRequest.class);
                seen.add(q);
                c.write(new StepResponse(k, q.moveMm(), q.turnDeg(), "", 0, 0, 0, new double[8], List.of(),
                        List.of()));
            }
            c.writeStep(Protocol.END_OF_SIMULATION);
            c.write(new SimulationEnd(steps - 1, "scripted end"));
            c.flush();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }
}
