package robosim.hardware;

import java.io.IOException;
import java.net.Socket;
import java.net.UnknownHostException;
import robosim.api.RobotControl;
import robosim.protocol.Connector;
import robosim.hardware.link.ScriptControl;
import robosim.protocol.ControlClasses;
import robosim.protocol.ControlScripts;
import robosim.protocol.SimulationKeys;

/** Starts one robot: finds its control class and type, connects, runs until the simulation ends. */
final class RobotLauncher {
    private RobotLauncher() {
    }

    /**
     * Instantiates a control class by name, found where {@link ControlClasses} says, or the control code that runs
     * a script ({@code python:PATH}, {@link ScriptControl}); a bad name is an IllegalArgumentException saying why.
     */
    static RobotControl control(String className) {
        if (ControlScripts.isScript(className)) {
            return new ScriptControl(className);
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
    static HardwareSimulator connect(String name, RobotType type, String host, int port, ConnectOptions options)
            throws IOException, InterruptedException {
        HardwareSimulator sim = new HardwareSimulator(name, type);
        Socket socket = open(host, port, options);
        try {
            sim.connect(socket, options.resetEvery, SimulationKeys.fromEnvironment(), options.connectTimeoutMs());
        } catch (IOException e) {
            throw new IOException(host + ":" + port + ": " + e.getMessage(), e);
        }
        return sim;
    }

    /** Opens a connection to the Environment's robot port; a failure is one line naming the host and port. */
    static Socket open(String host, int port, ConnectOptions options) throws IOException, InterruptedException {
        Socket socket;
        try {
            socket = Connector.connect(host, port, options.connectTimeoutMs(), options::waiting);
        } catch (UnknownHostException e) {
            throw new UnknownHostException("cannot connect to the Environment at " + host + ":" + port + ": "
                    + e.getMessage());
        } catch (IOException e) {
            throw new IOException("cannot connect to the Environment at " + host + ":" + port + ": " + e.getMessage());
        }
        if (socket == null) {
            throw new IOException("cannot connect to the Environment at " + host + ":" + port + " within "
                    + options.connectTimeoutS + " s (is it running, on that port?)");
        }
        return socket;
    }
}
