package robosim.environment.run;

import java.net.InetAddress;
import robosim.protocol.InMemoryLink;
import robosim.environment.server.ServerContext;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.SimulationKeys;

/**
 * How one simulation runs, in three named groups: where it listens ({@link Ports}), how long it waits
 * ({@link Timeouts}) and the run's shape ({@link Shape}: design, geometry, steps, pace). Build one with
 * {@link #builder()}; every value has a default a user would expect: loopback, the paper's ports, the
 * paper's design ({@code THREADS}), a Geometry process, as fast as possible, until stopped, a lost robot
 * removed; the file the run is recorded into ({@code record}, null: none) and whether with the robots' sensor readings
 * ({@code recordReadings}); the directory the world's loop functions
 * write their own files into ({@code outputDir}, made when they start; null: the working directory); and what starts the file's robots in
 * the Environment's own JVM ({@code robotsInThisJvm}, {@code --one-jvm}; null: every robot connects). Whether the
 * coordinator design allows these (the loss policy, robots in this JVM) is checked once, as one is built.
 */
public record Settings(Ports ports, Timeouts timeouts, Shape shape, java.nio.file.Path record,
        boolean recordReadings, java.nio.file.Path outputDir, InMemoryLink.Starter robotsInThisJvm) {
    /** Default step and Geometry timeouts, ms (the server's own defaults: {@link ServerContext}). */
    public static final long DEFAULT_STEP_TIMEOUT_MS = 60_000;
    public static final long DEFAULT_GEOMETRY_TIMEOUT_MS = 10_000;

    /**
     * Listening: the address and the robot, viewer and Geometry ports (0: a free one), how many
     * connections each port holds at once beyond the robots the file names or lets join (one more is closed at once),
     * and the keys every client must prove in its handshake, with TLS when they hold a key pair (null: none,
     * loopback only).
     */
    public record Ports(InetAddress bind, int robot, int viewer, int geometry, int maxConnections,
            SimulationKeys keys) {
    }

    /**
     * Waiting, ms (0 or less: never): for a client's hello (a deadline from the connection, not a
     * per-read timeout); for a robot's request after its step went
     * out; for Geometry's answer to a step; for a robot or viewer to take one write.
     */
    public record Timeouts(int handshakeMs, long stepMs, long geometryMs, long writeMs) {
    }

    /**
     * The run: the coordinator design; geometry in-process ({@code --no-geometry}) or a Geometry process
     * and what to do when it is lost; steps to run (0: until stopped); the pace ({@code speed} times real
     * time, 0 as fast as possible); the step number after every response ({@code stepMessages}, else only
     * step 0 and robots count on); the object streams' reset interval; what to do when a robot is lost; whether the
     * run counts its built-in metrics as it goes ({@code liveMetrics}: each released world carries them; a sweep reads
     * them from the recording instead).
     */
    public record Shape(CoordinatorDesign design, boolean inProcessGeometry,
            GeometryLoss onGeometryLoss, long maxSteps, double speed, boolean stepMessages,
            int resetEvery, RobotLoss onRobotLoss, boolean liveMetrics) {
    }

    public static Builder builder() {
        return new Builder();
    }

    public Builder toBuilder() {
        Builder b = new Builder();
        b.ports(bind(), robotPort(), viewerPort(), geometryPort());
        b.maxConnections = ports.maxConnections();
        b.keys = ports.keys();
        b.handshakeTimeoutMs = timeouts.handshakeMs();
        b.stepTimeoutMs = timeouts.stepMs();
        b.geometryTimeoutMs = timeouts.geometryMs();
        b.writeTimeoutMs = timeouts.writeMs();
        b.design = shape.design();
        b.inProcessGeometry = shape.inProcessGeometry();
        b.onGeometryLoss = shape.onGeometryLoss();
        b.maxSteps = shape.maxSteps();
        b.speed = shape.speed();
        b.stepMessages = shape.stepMessages();
        b.resetEvery = shape.resetEvery();
        b.onRobotLoss = shape.onRobotLoss();
        b.liveMetrics = shape.liveMetrics();
        b.record = record;
        b.recordReadings = recordReadings;
        b.outputDir = outputDir;
        b.robotsInThisJvm = robotsInThisJvm;
        return b;
    }

    public InetAddress bind() {
        return ports.bind();
    }

    public int robotPort() {
        return ports.robot();
    }

    public int viewerPort() {
        return ports.viewer();
    }

    public int geometryPort() {
        return ports.geometry();
    }

    public int maxConnections() {
        return ports.maxConnections();
    }

    public SimulationKeys keys() {
        return ports.keys();
    }

    public int handshakeTimeoutMs() {
        return timeouts.handshakeMs();
    }

    public long stepTimeoutMs() {
        return timeouts.stepMs();
    }

    public long geometryTimeoutMs() {
        return timeouts.geometryMs();
    }

    public long writeTimeoutMs() {
        return timeouts.writeMs();
    }

    public CoordinatorDesign design() {
        return shape.design();
    }

    public boolean inProcessGeometry() {
        return shape.inProcessGeometry();
    }

    public GeometryLoss onGeometryLoss() {
        return shape.onGeometryLoss();
    }

    public RobotLoss onRobotLoss() {
        return shape.onRobotLoss();
    }

    public long maxSteps() {
        return shape.maxSteps();
    }

    public double speed() {
        return shape.speed();
    }

    public boolean stepMessages() {
        return shape.stepMessages();
    }

    public int resetEvery() {
        return shape.resetEvery();
    }

    /** The run counts its built-in metrics as it goes. */
    public boolean liveMetrics() {
        return shape.liveMetrics();
    }

    /** Builds {@link Settings}; each setter changes one value. */
    public static final class Builder {
        private InetAddress bind = InetAddress.getLoopbackAddress();
        private int robotPort = Protocol.DEFAULT_ROBOT_PORT;
        private int viewerPort = Protocol.DEFAULT_VIEWER_PORT;
        private int geometryPort = Protocol.DEFAULT_GEOMETRY_PORT;
        private int maxConnections = ServerContext.DEFAULT_MAX_CONNECTIONS;
        private SimulationKeys keys;
        private int handshakeTimeoutMs = ServerContext.DEFAULT_HANDSHAKE_TIMEOUT_MS;
        private long stepTimeoutMs = DEFAULT_STEP_TIMEOUT_MS;
        private long geometryTimeoutMs = DEFAULT_GEOMETRY_TIMEOUT_MS;
        private long writeTimeoutMs = ServerContext.DEFAULT_WRITE_TIMEOUT_MS;
        private CoordinatorDesign design = CoordinatorDesign.THREADS;
        private boolean inProcessGeometry;
        private GeometryLoss onGeometryLoss = GeometryLoss.IN_PROCESS;
        private long maxSteps;
        private double speed;
        private boolean stepMessages = true;
        private int resetEvery = ObjectConnection.DEFAULT_RESET_EVERY;
        private java.nio.file.Path record;
        private boolean recordReadings = true;
        private java.nio.file.Path outputDir;
        private RobotLoss onRobotLoss = RobotLoss.REMOVE;
        private boolean liveMetrics;
        private InMemoryLink.Starter robotsInThisJvm;

        private Builder() {
        }

        /** Where to listen: the address and the robot, viewer and Geometry ports (0: a free one). */
        public Builder ports(InetAddress bindTo, int robot, int viewer, int geometry) {
            this.bind = bindTo;
            this.robotPort = robot;
            this.viewerPort = viewer;
            this.geometryPort = geometry;
            return this;
        }

        public Builder maxConnections(int perPort) {
            this.maxConnections = perPort;
            return this;
        }

        /** The keys every client proves in its handshake, and TLS if they hold a key pair (null: none). */
        public Builder keys(SimulationKeys s) {
            this.keys = s;
            return this;
        }

        public Builder handshakeTimeoutMs(int ms) {
            this.handshakeTimeoutMs = ms;
            return this;
        }

        public Builder stepTimeoutMs(long ms) {
            this.stepTimeoutMs = ms;
            return this;
        }

        public Builder geometryTimeoutMs(long ms) {
            this.geometryTimeoutMs = ms;
            return this;
        }

        public Builder writeTimeoutMs(long ms) {
            this.writeTimeoutMs = ms;
            return this;
        }

        public Builder design(CoordinatorDesign d) {
            this.design = d;
            return this;
        }

        public Builder inProcessGeometry(boolean on) {
            this.inProcessGeometry = on;
            return this;
        }

        public Builder onGeometryLoss(GeometryLoss policy) {
            this.onGeometryLoss = policy;
            return this;
        }

        public Builder onRobotLoss(RobotLoss policy) {
            this.onRobotLoss = policy;
            return this;
        }

        public Builder maxSteps(long steps) {
            this.maxSteps = steps;
            return this;
        }

        public Builder speed(double timesRealTime) {
            this.speed = timesRealTime;
            return this;
        }

        public Builder stepMessages(boolean on) {
            this.stepMessages = on;
            return this;
        }

        public Builder resetEvery(int messages) {
            this.resetEvery = messages;
            return this;
        }

        /** The run counts its built-in metrics as it goes (the testkit's {@code Simulation.metric}); off by default. */
        public Builder liveMetrics(boolean on) {
            this.liveMetrics = on;
            return this;
        }

        /** Records the run into this file, which must not exist yet ({@code --record}; null: no recording). */
        public Builder record(java.nio.file.Path file) {
            this.record = file;
            return this;
        }

        /** Whether the recording holds the robots' sensor readings ({@code --record-without-readings}: not). */
        public Builder recordReadings(boolean readings) {
            this.recordReadings = readings;
            return this;
        }

        /** The world's loop functions write their own files here ({@code --output-dir}; null: the working directory). */
        public Builder outputDir(java.nio.file.Path dir) {
            this.outputDir = dir;
            return this;
        }

        /**
         * Runs every robot the file names in the Environment's JVM, started by {@code starter} with its type and
         * control class, through an in-memory link (no socket, no serialization); robots that join later still
         * connect. Null: every robot connects.
         */
        public Builder robotsInThisJvm(InMemoryLink.Starter starter) {
            this.robotsInThisJvm = starter;
            return this;
        }

        /** @throws IllegalArgumentException what the coordinator design does not allow of these settings, saying why */
        public Settings build() {
            String refusal = design.refusesLossPolicy(onRobotLoss);
            if (refusal == null && robotsInThisJvm != null) {
                refusal = design.refuses(Transport.IN_MEMORY);
            }
            if (refusal != null) {
                throw new IllegalArgumentException(refusal);
            }
            return new Settings(new Ports(bind, robotPort, viewerPort, geometryPort, maxConnections, keys),
                    new Timeouts(handshakeTimeoutMs, stepTimeoutMs, geometryTimeoutMs, writeTimeoutMs),
                    new Shape(design, inProcessGeometry, onGeometryLoss, maxSteps, speed, stepMessages, resetEvery,
                            onRobotLoss, liveMetrics),
                    record, recordReadings, outputDir, robotsInThisJvm);
        }
    }
}
