import java.io.*;
import java.net.*;
import java.util.Arrays;

/**
 * The floor of the cheapest shape with a socket per robot, the one the `SEQUENTIAL` coordinator is
 * measured against: ONE server thread reads every client's request in turn and then writes every reply
 * and the next step number, and ONE client thread owns all N client sockets (for each, it reads the step
 * number and writes the request; then it reads every reply). A request and a reply are the same small
 * Externalizable message (robot, two doubles, the step, 16 sonar ranges), written unshared through object
 * streams reset every 256 messages, as the Environment's connections. Nothing is simulated. The clock
 * starts before the first step number is written and stops after the last reply.
 * usage: java bench/FloorShared.java N STEPS
 * Prints one line: clients=N steps=S mode=shared wall=Ws steps/s=R robot-steps/s=R.
 * bench/FloorThreads.java is the same exchange with a reader thread per socket on the server.
 */
public class FloorShared {
    /** A request or a reply. */
    public static final class Msg implements Externalizable {
        public int robot;
        public double dx, dtheta;
        public long step;
        public double[] sonar = new double[16];

        public Msg() {
        }

        @Override
        public void writeExternal(ObjectOutput out) throws IOException {
            out.writeInt(robot);
            out.writeDouble(dx);
            out.writeDouble(dtheta);
            out.writeLong(step);
            out.writeShort(sonar.length);
            for (double range : sonar) {
                out.writeDouble(range);
            }
        }

        @Override
        public void readExternal(ObjectInput in) throws IOException {
            robot = in.readInt();
            dx = in.readDouble();
            dtheta = in.readDouble();
            step = in.readLong();
            sonar = new double[in.readShort()];
            for (int i = 0; i < sonar.length; i++) {
                sonar[i] = in.readDouble();
            }
        }
    }

    /** One end of a socket: its object streams, reset every RESET_EVERY messages written. */
    static final class End {
        static final int RESET_EVERY = 256;
        final ObjectOutputStream out;
        final ObjectInputStream in;
        private int written;

        End(Socket socket) throws IOException {
            socket.setTcpNoDelay(true);
            out = new ObjectOutputStream(new BufferedOutputStream(socket.getOutputStream()));
            out.flush();
            in = new ObjectInputStream(new BufferedInputStream(socket.getInputStream()));
        }

        void write(Msg message) throws IOException {
            out.writeUnshared(message);
            if (++written % RESET_EVERY == 0) {
                out.reset();
            }
        }
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 2 || args[0].equals("--help") || args[0].equals("-h")) {
            System.out.println("usage: java bench/FloorShared.java N STEPS");
            return;
        }
        int clients = positive("N", args[0]);
        int steps = positive("STEPS", args[1]);
        ServerSocket server = new ServerSocket(0, 4096, InetAddress.getLoopbackAddress());
        Thread client = new Thread(() -> runClients(server.getLocalPort(), clients, steps), "clients");
        client.setDaemon(true);
        client.start();

        Socket[] accepted = new Socket[clients];
        for (int c = 0; c < clients; c++) {
            accepted[c] = server.accept();
        }
        End[] ends = new End[clients];
        for (int c = 0; c < clients; c++) {
            ends[c] = new End(accepted[c]);
        }
        long start = System.nanoTime();
        for (End end : ends) {
            end.out.writeLong(0);
            end.out.flush();
        }
        Msg[] requests = new Msg[clients];
        for (int k = 0; k < steps; k++) {
            for (int c = 0; c < clients; c++) {
                requests[c] = (Msg) ends[c].in.readObject();
            }
            for (int c = 0; c < clients; c++) {
                Msg reply = requests[c];
                reply.dx *= 2;
                Arrays.fill(reply.sonar, 5000.0);
                ends[c].write(reply);
                if (k + 1 < steps) {
                    ends[c].out.writeLong(k + 1);
                }
                ends[c].out.flush();
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        System.out.printf("clients=%d steps=%d mode=shared wall=%.3fs steps/s=%.1f robot-steps/s=%.0f%n",
                clients, steps, seconds, steps / seconds, (double) clients * steps / seconds);
    }

    /** The client side: one thread, every socket; per step each client's request, then every reply. */
    static void runClients(int port, int clients, int steps) {
        try {
            Socket[] sockets = new Socket[clients];
            for (int c = 0; c < clients; c++) {
                sockets[c] = new Socket(InetAddress.getLoopbackAddress(), port);
            }
            End[] ends = new End[clients];
            for (int c = 0; c < clients; c++) {
                ends[c] = new End(sockets[c]);
            }
            for (int k = 0; k < steps; k++) {
                for (int c = 0; c < clients; c++) {
                    Msg request = new Msg();
                    request.robot = c;
                    request.step = ends[c].in.readLong();
                    request.dx = 0.25;
                    ends[c].write(request);
                    ends[c].out.flush();
                }
                for (End end : ends) {
                    end.in.readObject();
                }
            }
        } catch (Exception e) {
            e.printStackTrace();
        }
    }

    static int positive(String name, String value) {
        int n = Integer.parseInt(value);
        if (n <= 0) {
            throw new IllegalArgumentException(name + " must be > 0, got " + value);
        }
        return n;
    }
}
