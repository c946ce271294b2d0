import java.io.*;
import java.net.*;
import java.util.concurrent.*;

/**
 * The floor of the thread-per-client shape on both sides: what a lock-step exchange over loopback sockets
 * costs this machine with nothing simulated. N clients, each a thread with its own socket; on the server one
 * thread per client. A step, for every client: the server thread writes the step number, the client answers
 * with a small request (robot, two doubles, the step), the server threads wait for each other at a barrier
 * (the step is whole when every request is in), and each writes its client's request back, changed, as the
 * reply. The clock starts when every server thread is ready to begin and stops when the last has finished.
 * usage: java bench/Floor.java N STEPS [obj|raw|obj-nostep|raw-nostep] [RESET_EVERY]
 * obj (the default): Externalizable objects through object streams reset every RESET_EVERY (default 100)
 * messages, as the Environment's connections; raw: the same fields through data streams; -nostep: no step
 * number before a step. Prints one line: clients=N steps=S mode=M wall=Ws steps/s=R robot-steps/s=R.
 * bench/FloorProcesses.java is this floor with every client its own JVM; bench/FloorThreads.java and
 * bench/FloorShared.java are the cheapest shapes with a socket per robot.
 */
public class Floor {
    /** The request, and the reply (the same fields, dx doubled): 28 bytes of fields. */
    public static final class Req implements Externalizable {
        public int robot;
        public double dx, dtheta;
        public long step;

        public Req() {
        }

        @Override
        public void writeExternal(ObjectOutput out) throws IOException {
            writeFields(out);
        }

        @Override
        public void readExternal(ObjectInput in) throws IOException {
            readFields(in);
        }

        void writeFields(DataOutput out) throws IOException {
            out.writeInt(robot);
            out.writeDouble(dx);
            out.writeDouble(dtheta);
            out.writeLong(step);
        }

        void readFields(DataInput in) throws IOException {
            robot = in.readInt();
            dx = in.readDouble();
            dtheta = in.readDouble();
            step = in.readLong();
        }
    }

    /** One end of one client's socket, in the chosen mode. */
    interface Wire {
        void writeStep(long step) throws IOException;

        long readStep() throws IOException;

        /** Writes a message (and, as objects, resets the stream when step % resetEvery == 0) and flushes. */
        void write(Req message, long step) throws IOException;

        Req read() throws IOException, ClassNotFoundException;
    }

    /** Externalizable objects through object streams. */
    static final class ObjectWire implements Wire {
        private final ObjectOutputStream out;
        private final ObjectInputStream in;
        private final int resetEvery;

        ObjectWire(Socket socket, int resetEvery) throws IOException {
            out = new ObjectOutputStream(new BufferedOutputStream(socket.getOutputStream()));
            out.flush();
            in = new ObjectInputStream(new BufferedInputStream(socket.getInputStream()));
            this.resetEvery = resetEvery;
        }

        @Override
        public void writeStep(long step) throws IOException {
            out.writeLong(step);
            out.flush();
        }

        @Override
        public long readStep() throws IOException {
            return in.readLong();
        }

        @Override
        public void write(Req message, long step) throws IOException {
            out.writeObject(message);
            if (step % resetEvery == 0) {
                out.reset();
            }
            out.flush();
        }

        @Override
        public Req read() throws IOException, ClassNotFoundException {
            return (Req) in.readObject();
        }
    }

    /** The same fields through data streams, read into one reused message. */
    static final class DataWire implements Wire {
        private final DataOutputStream out;
        private final DataInputStream in;
        private final Req received = new Req();

        DataWire(Socket socket) throws IOException {
            out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
            in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
        }

        @Override
        public void writeStep(long step) throws IOException {
            out.writeLong(step);
            out.flush();
        }

        @Override
        public long readStep() throws IOException {
            return in.readLong();
        }

        @Override
        public void write(Req message, long step) throws IOException {
            message.writeFields(out);
            out.flush();
        }

        @Override
        public Req read() throws IOException {
            received.readFields(in);
            return received;
        }
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 2 || args[0].equals("--help") || args[0].equals("-h")) {
            System.out.println("usage: java bench/Floor.java N STEPS [obj|raw|obj-nostep|raw-nostep] [RESET_EVERY]");
            return;
        }
        int clients = positive("N", args[0]);
        int steps = positive("STEPS", args[1]);
        String mode = args.length > 2 ? args[2] : "obj";
        if (!mode.matches("(obj|raw)(-nostep)?")) {
            throw new IllegalArgumentException("mode must be obj, raw, obj-nostep or raw-nostep, got " + mode);
        }
        boolean objects = mode.startsWith("obj");
        boolean stepMessages = !mode.endsWith("-nostep");
        int resetEvery = args.length > 3 ? positive("RESET_EVERY", args[3]) : 100;

        ServerSocket server = new ServerSocket(0, 4096, InetAddress.getLoopbackAddress());
        for (int c = 0; c < clients; c++) {
            int robot = c;
            Thread client = new Thread(() -> runClient(server.getLocalPort(), robot, steps, objects, stepMessages,
                    resetEvery), "client-" + c);
            client.setDaemon(true);
            client.start();
        }
        CyclicBarrier stepComplete = new CyclicBarrier(clients);
        CountDownLatch ready = new CountDownLatch(clients);
        CountDownLatch finished = new CountDownLatch(clients);
        Thread[] workers = new Thread[clients];
        for (int c = 0; c < clients; c++) {
            Socket socket = server.accept();
            socket.setTcpNoDelay(true);
            workers[c] = new Thread(() -> {
                try {
                    Wire wire = objects ? new ObjectWire(socket, resetEvery) : new DataWire(socket);
                    ready.countDown();
                    ready.await();
                    for (long k = 0; k < steps; k++) {
                        if (stepMessages) {
                            wire.writeStep(k);
                        }
                        Req request = wire.read();
                        stepComplete.await();
                        request.dx *= 2;
                        wire.write(request, k);
                    }
                } catch (Exception e) {
                    e.printStackTrace();
                }
                finished.countDown();
            }, "worker-" + c);
        }
        long start = System.nanoTime();
        for (Thread worker : workers) {
            worker.start();
        }
        finished.await();
        double seconds = (System.nanoTime() - start) / 1e9;
        System.out.printf("clients=%d steps=%d mode=%s wall=%.3fs steps/s=%.0f robot-steps/s=%.0f%n",
                clients, steps, mode, seconds, steps / seconds, (double) clients * steps / seconds);
    }

    /** One client: for every step, the step number (or its own count), its request, the reply. */
    static void runClient(int port, int robot, int steps, boolean objects, boolean stepMessages, int resetEvery) {
        try (Socket socket = new Socket(InetAddress.getLoopbackAddress(), port)) {
            socket.setTcpNoDelay(true);
            Wire wire = objects ? new ObjectWire(socket, resetEvery) : new DataWire(socket);
            Req request = new Req();
            request.robot = robot;
            for (long k = 0; k < steps; k++) {
                request.step = stepMessages ? wire.readStep() : k;
                request.dx = 0.25;
                wire.write(request, k);
                wire.read();
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
