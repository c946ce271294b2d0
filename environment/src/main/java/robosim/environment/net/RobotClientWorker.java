package robosim.environment.net;

import robosim.environment.server.Handshake;
import robosim.environment.server.ClientWorker;
import robosim.environment.server.Port;
import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import robosim.protocol.RobotHello;
import robosim.protocol.SharedHello;

/**
 * The report's thread per client on the robot port: its thread, {@code robot-worker[#n]}, reads the
 * client's first message and serves it as what that says it is: one robot over its own socket
 * ({@link RobotConnection}, the thread then named {@code robot-worker[name]}) or several robots of one
 * process over one ({@link SharedConnection}, {@code robot-worker[shared #n]}). Both use this connection's
 * {@link Handshake}. Another kind of client's hello is told which port it wants ({@link Port}); anything else
 * is refused as its class is read (the connection is dropped with the reason).
 */
final class RobotClientWorker extends ClientWorker {
    private final ClientWorkerCoordinator coordinator;
    private final int serial;
    private volatile RobotConnection robot;
    private volatile SharedConnection shared;

    RobotClientWorker(ClientWorkerCoordinator coordinator, Socket socket, int serial) {
        super(coordinator.server(), socket, "robot-worker[#" + serial + "]", Port.ROBOT);
        this.coordinator = coordinator;
        this.serial = serial;
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        Externalizable first = handshake.hello(port);
        if (first instanceof SharedHello h) {
            rename("robot-worker[shared #" + serial + "]");
            SharedConnection s = new SharedConnection(this, coordinator, connection, handshake);
            shared = s;
            s.serve(h);
        } else {
            RobotHello hello = (RobotHello) first;
            RobotConnection r = new RobotConnection(this, coordinator, connection, String.valueOf(hello.name()));
            robot = r;
            r.serve(hello, handshake);
        }
    }

    @Override
    protected void exited(String why) {
        RobotConnection r = robot;
        if (r != null) {
            r.exited(why);
        }
        SharedConnection s = shared;
        if (s != null) {
            s.exited(why);
        }
    }
}
