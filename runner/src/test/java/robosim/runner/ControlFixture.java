package robosim.runner;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import robosim.control.ControlClient;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.control.ControlServer;
import robosim.environment.control.EnvironmentDirectories;
import robosim.environment.control.EnvironmentHost;
import robosim.environment.run.Settings;
import robosim.examples.BackAndForth;
import robosim.hardware.HardwareSimulator;
import robosim.devices.RobotType;
import robosim.protocol.SimulationKeys;

/** An Environment host with its control port, on ephemeral ports; paused until told. */
final class ControlFixture implements AutoCloseable {
    /** Sends {@code request} over {@code control}, which must answer ok; its message. */
    static String ok(ControlClient control, String request) throws IOException {
        JsonNode r = control.request(request);
        org.junit.jupiter.api.Assertions.assertTrue(r.path("ok").asBoolean(), request + ": " + r);
        return r.path("message").asText();
    }

    static final int TIMEOUT_MS = 60_000;
    /** The control port's proof deadline (the Environment's: its handshake deadline, 10 s by default). */
    static final int DEFAULT_PROOF_DEADLINE_MS = 10_000;

    final EnvironmentHost host;
    final ControlServer control;
    final CompletableFuture<Integer> running;
    /** Every robot's socket, in file order, for each call of {@link #robots}: a test may close one. */
    final List<Socket> sockets = new ArrayList<>();

    /** @param keys the simulation's keys (null: none) */
    ControlFixture(Path file, SimulationKeys keys) throws Exception {
        this(file, keys, 0, DEFAULT_PROOF_DEADLINE_MS);
    }

    /** @param speed the run's pace in times real time (0: as fast as possible) */
    ControlFixture(Path file, SimulationKeys keys, double speed) throws Exception {
        this(file, keys, speed, DEFAULT_PROOF_DEADLINE_MS);
    }

    /** @param proofDeadlineMs how long a connection may take to prove the keys' secret */
    ControlFixture(Path file, SimulationKeys keys, double speed, int proofDeadlineMs) throws Exception {
        Settings s = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true)
                .resetEvery(64).speed(speed).build();
        host = new EnvironmentHost(file, new EnvironmentLoader().load(file), s, true, true);
        host.open();
        // load may read the tests' files and the bundled environments
        control = new ControlServer(new robosim.environment.control.EnvironmentCommands(host, new EnvironmentDirectories(
                List.of(file.toAbsolutePath().getParent(), InJvmSimulation.env("test.xml").getParent()))), keys,
                proofDeadlineMs);
        control.start(InetAddress.getLoopbackAddress(), 0);
        running = CompletableFuture.supplyAsync(() -> {
            try {
                return host.run(summary -> { });
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        }, TestThreads.ROBOTS);
    }

    ControlClient client(SimulationKeys keys) throws IOException {
        return new ControlClient("127.0.0.1", control.port(), keys, TIMEOUT_MS);
    }

    /** Connects every robot of the current file, each running BackAndForth; their end reasons. */
    List<CompletableFuture<String>> robots() throws Exception {
        int port = host.ports()[0];
        List<CompletableFuture<String>> out = new ArrayList<>();
        for (var r : new EnvironmentLoader().load(host.file()).robots()) {
            HardwareSimulator sim = new HardwareSimulator(r.name(), robosim.devices.RobotTypes.byName(r.type()));
            Socket socket = new Socket(InetAddress.getLoopbackAddress(), port);
            sockets.add(socket);
            sim.connect(socket, 64);
            out.add(CompletableFuture.supplyAsync(() -> {
                try {
                    return sim.run(new BackAndForth());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, TestThreads.ROBOTS));
        }
        return out;
    }

    @Override
    public void close() throws Exception {
        host.shutdown();
        running.get(TIMEOUT_MS, TimeUnit.MILLISECONDS);
        control.close();
        host.current().close();
    }
}
