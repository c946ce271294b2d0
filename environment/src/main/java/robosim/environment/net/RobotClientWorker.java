package robosim.environment.net;

import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import robosim.environment.server.ClientWorker;
import robosim.environment.server.Port;
import robosim.environment.server.ServerContext;
import robosim.protocol.RobotHello;
import robosim.protocol.SharedHello;

/**
 * The report's thread per client on the robot port: its thread, {@code robot-worker[#n]}, reads the
 * client's first message and serves it as what that says it is: one robot over its own socket
 * ({@link RobotConnection}, the thread then named {@code robot-worker[name]}) or several robots of one
 * process over one ({@link SharedConnection}, {@code robot-worker[shared #n]}). Both use this connection's
 * handshake. Another kind of client's hello is told which port it wants; anything else is refused as its class is
 * read (the connection is dropped with the reason).
 */
final class RobotClientWorker extends ClientWorker {
    private final RobotContext robots;
    /** Where shared connections' frames wait to be written. */
    private final SharedOutput frames;
    private final int serial;
    private volatile RobotConnection robot;
    private volatile SharedConnection shared;

    RobotClientWorker(ServerContext server, RobotContext robots, SharedOutput frames, Socket socket, int serial) {
        super(server, socket, "robot-worker[#" + serial + "]", Port.ROBOT);
        this.robots = robots;
        this.frames = frames;
        this.serial = serial;
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        Externalizable first = handshake.hello(port);
        if (first instanceof SharedHello h) {
            rename("robot-worker[shared #" + serial + "]");
            SharedConnection s = new SharedConnection(this, robots, frames, connection, handshake);
            shared = s;
            s.serve(h);
        } else {
            RobotHello hello = (RobotHello) first;
            RobotConnection r = new RobotConnection(this, robots, connection, String.valueOf(hello.name()));
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
