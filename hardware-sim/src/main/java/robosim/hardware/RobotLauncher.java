package robosim.hardware;

import robosim.devices.RobotType;
import java.io.IOException;
import java.net.Socket;
import java.net.UnknownHostException;
import java.util.concurrent.atomic.AtomicBoolean;
import robosim.api.RobotControl;
import robosim.protocol.ClientOptions;
import robosim.protocol.ConnectOptions;
import robosim.protocol.Connector;
import robosim.hardware.link.ScriptControl;
import robosim.protocol.ControlClasses;
import robosim.protocol.ControlScripts;
import robosim.protocol.SimulationKeys;

/**
 * Starts a process's robots: finds each one's control class and type, and connects it to the Environment at
 * {@code host:port}, trying for the connect timeout; says once per process that it waits for the Environment.
 */
final class RobotLauncher {
    private final String host;
    private final int port;
    private final ConnectOptions connect;
    private final int resetEvery;
    private final AtomicBoolean toldWaiting = new AtomicBoolean();

    RobotLauncher(String host, int port, ClientOptions client) {
        this.host = host;
        this.port = port;
        this.connect = client.connect();
        this.resetEvery = client.resetEvery();
    }

    /** Messages between the connections' stream resets. */
    int resetEvery() {
        return resetEvery;
    }

    /** How long a connection is tried for, ms. */
    long connectTimeoutMs() {
        return connect.millis();
    }

    /**
     * Instantiates a control class by name, found where {@link ControlClasses} says, or the control code that runs
     * a script ({@code python:PATH}, {@link ScriptControl}); a bad name is an IllegalArgumentException saying why.
     */
    static RobotControl control(String className) {
        if (ControlScripts.isScript(className)) {
            return new ScriptControl(className);
        }
        if (ControlScripts.isRos2(className)) {
            throw new IllegalArgumentException("control ros2: " + ControlScripts.ros2Elsewhere());
        }
        try {
            return Class.forName(className, true, ControlClasses.loader()).asSubclass(RobotControl.class)
                    .getDeclaredConstructor().newInstance();
        } catch (ClassNotFoundException e) {
            throw new IllegalArgumentException("control class " + className + " is not on the class path");
        } catch (ClassCastException e) {
            throw new IllegalArgumentException("control class " + className + " does not implement "
                    + RobotControl.class.getName());
        } catch (java.lang.reflect.InvocationTargetException e) {
            throw new IllegalArgumentException("control class " + className + "'s constructor threw " + e.getCause());
        } catch (LinkageError e) {
            throw new IllegalArgumentException("control class " + className + " could not be loaded: " + e);
        } catch (ReflectiveOperationException e) {
            throw new IllegalArgumentException("control class " + className
                    + " needs a public no-argument constructor");
        }
    }

    /**
     * Connects and says hello; the simulator returned is ready to run. A failure to connect, or a refusal, is
     * an IOException whose message is one line naming the host and port and what answered there (a port of
     * another kind says which it is; one that answers nothing ends within the connect timeout).
     */
    HardwareSimulator connect(String name, RobotType type) throws IOException, InterruptedException {
        HardwareSimulator sim = new HardwareSimulator(name, type);
        Socket socket = open();
        try {
            sim.connect(socket, resetEvery, SimulationKeys.fromEnvironment(), connect.millis());
        } catch (IOException e) {
            throw new IOException(host + ":" + port + ": " + e.getMessage(), e);
        }
        return sim;
    }

    /** Opens a connection to the Environment's robot port; a failure is one line naming the host and port. */
    Socket open() throws IOException, InterruptedException {
        Socket socket;
        try {
            socket = Connector.connect(host, port, connect.millis(), line -> {
                if (toldWaiting.compareAndSet(false, true)) {
                    System.err.println(line);
                }
            });
        } catch (UnknownHostException e) {
            throw new UnknownHostException("cannot connect to the Environment at " + host + ":" + port + ": "
                    + e.getMessage());
        } catch (IOException e) {
            throw new IOException("cannot connect to the Environment at " + host + ":" + port + ": " + e.getMessage());
        }
        if (socket == null) {
            throw new IOException("cannot connect to the Environment at " + host + ":" + port + " within "
                    + connect.seconds() + " s (is it running, on that port?)");
        }
        return socket;
    }
}
