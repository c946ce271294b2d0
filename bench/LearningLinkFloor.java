import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import robosim.protocol.link.LinkFrames;

/**
 * The floor of the learning link's shape: a learner in another process sending one step's actions for K worlds of N
 * robots and taking the step's arrays back, over the link's frames, from a server that answers each at once with a
 * reply packed once (the arrays of K worlds of N robots of S sonars), no simulation behind it: the least a step seen
 * from Python can cost. The learner (PYTHON, with python/src on its path) does a step's wire work as robosim.rl's
 * LearningHost does: the actions to bytes, one frame out, one in, MessagePack, numpy views of the arrays.
 * usage: java -cp 'runner/target/lib/*:runner/target/runner-*.jar' bench/LearningLinkFloor.java PYTHON WORLDS ROBOTS SONARS STEPS
 * Prints one line: worlds=K robots=N steps=S wall=Ws steps/s=R robot-steps/s=R us/step=U.
 */
public class LearningLinkFloor {
    public static void main(String[] args) throws Exception {
        String python = args[0];
        int worlds = Integer.parseInt(args[1]);
        int robots = Integer.parseInt(args[2]);
        int sonars = Integer.parseInt(args[3]);
        int steps = Integer.parseInt(args[4]);
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packArrayHeader(2).packString("ok").packMapHeader(5);
        int metrics = robosim.environment.metrics.Metrics.names().size(); // (the learning link's, BatchWorlds.METRICS)
        int[][] sizes = {{8 * worlds}, {worlds * robots * sonars * 4}, {worlds * robots * 12}, {worlds * robots},
                {worlds * metrics * 8}};
        String[] names = {"steps", "sonar", "pose", "contact", "metrics"};
        for (int i = 0; i < names.length; i++) {
            p.packString(names[i]).packBinaryHeader(sizes[i][0]);
            p.writePayload(new byte[sizes[i][0]]);
        }
        byte[] reply = p.toByteArray();
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            String learner = """
                    import socket, sys, time
                    import numpy as np
                    from robosim.frames import Frames
                    port, k, n, s, steps, m = (int(a) for a in sys.argv[1:])
                    sock = socket.create_connection(("127.0.0.1", port))
                    sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
                    frames = Frames(sock)
                    shapes = [("steps", "<i8", (k,)), ("sonar", "<f4", (k, n, s)), ("pose", "<f4", (k, n, 3)),
                              ("contact", "u1", (k, n)), ("metrics", "<f8", (k, m))]
                    actions = np.zeros((k, n, 2), np.float32)
                    def step():
                        frames.send(["step", actions.astype("<f4", copy=False).tobytes(), None])
                        arrays = frames.receive()[1]
                        return [np.frombuffer(arrays[name], dtype=t).reshape(shape) for name, t, shape in shapes]
                    for _ in range(500):
                        step()
                    t0 = time.perf_counter()
                    for _ in range(steps):
                        step()
                    print(time.perf_counter() - t0)
                    """;
            ProcessBuilder pb = new ProcessBuilder(python, "-c", learner, Integer.toString(server.getLocalPort()),
                    Integer.toString(worlds), Integer.toString(robots), Integer.toString(sonars),
                    Integer.toString(steps), Integer.toString(metrics)).redirectError(ProcessBuilder.Redirect.INHERIT);
            pb.environment().put("PYTHONPATH", "python/src");
            Process learnerProcess = pb.start();
            try (Socket s = server.accept()) {
                s.setTcpNoDelay(true);
                DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
                DataOutputStream out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
                while (LinkFrames.read(in) != null) {
                    LinkFrames.write(out, reply);
                }
            }
            String said = new String(learnerProcess.getInputStream().readAllBytes()).trim();
            if (!learnerProcess.waitFor(60, TimeUnit.SECONDS) || learnerProcess.exitValue() != 0) {
                throw new IllegalStateException("the learner failed: " + said);
            }
            double wall = Double.parseDouble(said);
            System.out.printf(Locale.ROOT, "worlds=%d robots=%d steps=%d wall=%.3fs steps/s=%.1f robot-steps/s=%.1f "
                    + "us/step=%.1f%n", worlds, robots, steps, wall, steps / wall, (double) steps * worlds * robots / wall,
                    wall * 1e6 / steps);
        }
    }
}
