import java.io.*;
import java.net.*;
import java.util.Arrays;
import java.util.concurrent.Semaphore;

/**
 * The floor of the thread-per-client shape with a socket per robot, the one the default `THREADS`
 * coordinator and the shared connection are measured against: the report's ClientWorkerCoordinator built
 * as cheaply as that shape allows. On the server one reader thread per client socket reads its client's
 * request, counts it in, and waits until the loop has taken it before reading the next; ONE loop thread
 * waits until every request of the step is in, then writes every reply and the next step number itself.
 * ONE client thread owns all N client sockets. The messages, object streams and resets are those of
 * bench/FloorShared.java (one server thread, no hand-over), the cheapest shape with a socket per robot.
 * The clock starts once step 0's numbers are written, before the readers start, and stops after the last
 * reply.
 * usage: java bench/FloorThreads.java N STEPS [virtual]   (virtual: the readers are virtual threads, JDK 21+)
 * Prints one line: clients=N steps=S mode=threads wall=Ws steps/s=R robot-steps/s=R.
 */
public class FloorThreads {
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
            System.out.println("usage: java bench/FloorThreads.java N STEPS [virtual]");
            return;
        }
        int clients = positive("N", args[0]);
        int steps = positive("STEPS", args[1]);
        boolean virtual = args.length > 2 && args[2].equals("virtual");
        if (args.length > 2 && !virtual) {
            throw new IllegalArgumentException("the third argument may only be virtual, got " + args[2]);
        }
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
        Msg[] requests = new Msg[clients];
        Semaphore arrived = new Semaphore(0);
        Semaphore[] taken = new Semaphore[clients];
        for (int c = 0; c < clients; c++) {
            taken[c] = new Semaphore(1);
        }
        for (End end : ends) {
            end.out.writeLong(0);
            end.out.flush();
        }
        long start = System.nanoTime();
        for (int c = 0; c < clients; c++) {
            int robot = c;
            Runnable reader = () -> {
                try {
                    for (int k = 0; k < steps; k++) {
                        taken[robot].acquire();
                        requests[robot] = (Msg) ends[robot].in.readObject();
                        arrived.release();
                    }
                } catch (Exception e) {
                    e.printStackTrace();
                }
            };
            if (virtual) {
                startVirtual(reader);
            } else {
                Thread t = new Thread(reader, "reader-" + c);
                t.setDaemon(true);
                t.start();
            }
        }
        for (int k = 0; k < steps; k++) {
            arrived.acquire(clients);
            for (int c = 0; c < clients; c++) {
                Msg reply = requests[c];
                taken[c].release();
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
        System.out.printf("clients=%d steps=%d mode=threads wall=%.3fs steps/s=%.1f robot-steps/s=%.0f%n",
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

    /** A virtual thread, started; by reflection, so the floor also compiles and runs (without it) on JDK 17. */
    static void startVirtual(Runnable task) {
        try {
            Object builder = Thread.class.getMethod("ofVirtual").invoke(null);
            Class.forName("java.lang.Thread$Builder").getMethod("start", Runnable.class).invoke(builder, task);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("virtual threads need JDK 21+", e);
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
