import java.io.*;
import java.net.*;
import java.util.concurrent.*;

/**
 * bench/Floor.java with one change: each client runs in its own JVM, as robots do under headless.sh. The
 * server's thread shape (a thread per client, a barrier a step) and the messages are Floor.java's. It
 * measures what separate client processes cost on this machine, so a figure for robots as processes can be
 * set against both floors (scripts/bench-paper.sh runs them alternated).
 * usage: javac -d bench/classes bench/FloorProcesses.java; java -cp bench/classes FloorProcesses N STEPS [obj]
 * (its clients speak Floor.java's obj mode, reset every 100 messages: only obj, the default, fits them)
 * Prints one line: clients=N steps=S mode=M wall=Ws steps/s=R robot-steps/s=R.
 */
public class FloorProcesses {
    public static final class Req implements Externalizable {
        public int robot; public double dx, dtheta; public long step;
        public Req() {}
        public void writeExternal(ObjectOutput o) throws IOException { o.writeInt(robot); o.writeDouble(dx); o.writeDouble(dtheta); o.writeLong(step); }
        public void readExternal(ObjectInput i) throws IOException { robot = i.readInt(); dx = i.readDouble(); dtheta = i.readDouble(); step = i.readLong(); }
    }
    static void client(int port, int id, int steps) throws Exception {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            s.setTcpNoDelay(true);
            ObjectOutputStream out = new ObjectOutputStream(new BufferedOutputStream(s.getOutputStream())); out.flush();
            ObjectInputStream in = new ObjectInputStream(new BufferedInputStream(s.getInputStream()));
            Req r = new Req(); r.robot = id;
            for (int k = 0; k < steps; k++) {
                long st = in.readLong();
                r.step = st; r.dx = 0.25; out.writeObject(r); if (k % 100 == 0) out.reset(); out.flush();
                in.readObject();
            }
        }
    }
    public static void main(String[] a) throws Exception {
        if (a[0].equals("client")) { client(Integer.parseInt(a[1]), Integer.parseInt(a[2]), Integer.parseInt(a[3])); return; }
        int n = Integer.parseInt(a[0]); int steps = Integer.parseInt(a[1]);
        boolean obj = a.length < 3 || a[2].startsWith("obj"); boolean noStep = a.length > 2 && a[2].endsWith("-nostep"); int resetEvery = a.length > 3 ? Integer.parseInt(a[3]) : 100;
        ServerSocket ss = new ServerSocket(0, 4096, InetAddress.getLoopbackAddress());
        int port = ss.getLocalPort();
        CyclicBarrier barrier = new CyclicBarrier(n);
        CountDownLatch done = new CountDownLatch(n);
        for (int c = 0; c < n; c++) {
            new ProcessBuilder(System.getProperty("java.home") + "/bin/java", "-cp", System.getProperty("robosim.floor.cp", "bench/classes"), "FloorProcesses", "client", "" + port, "" + c, "" + steps).inheritIO().start();
        }
        Thread[] workers = new Thread[n];
        long[] t0 = new long[1];
        CountDownLatch ready = new CountDownLatch(n);
        for (int c = 0; c < n; c++) {
            Socket s = ss.accept(); s.setTcpNoDelay(true);
            workers[c] = new Thread(() -> {
                try {
                    if (obj) {
                        ObjectOutputStream out = new ObjectOutputStream(new BufferedOutputStream(s.getOutputStream())); out.flush();
                        ObjectInputStream in = new ObjectInputStream(new BufferedInputStream(s.getInputStream()));
                        ready.countDown(); ready.await();
                        for (int k = 0; k < steps; k++) {
                            if (!noStep) { out.writeLong(k); out.flush(); }
                            Req r = (Req) in.readObject();
                            barrier.await();
                            r.dx = r.dx * 2; out.writeObject(r); if (k % resetEvery == 0) out.reset(); out.flush();
                        }
                    } else {
                        DataOutputStream out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
                        DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
                        ready.countDown(); ready.await();
                        for (int k = 0; k < steps; k++) {
                            if (!noStep) { out.writeLong(k); out.flush(); }
                            int id = in.readInt(); double dx = in.readDouble(); double dt = in.readDouble(); long st = in.readLong();
                            barrier.await();
                            out.writeInt(id); out.writeDouble(dx * 2); out.writeDouble(dt); out.writeLong(st); out.flush();
                        }
                    }
                } catch (Exception e) { e.printStackTrace(); }
                done.countDown();
            });
        }
        long start = System.nanoTime();
        for (Thread w : workers) w.start();
        done.await();
        double secs = (System.nanoTime() - start) / 1e9;
        System.out.printf("clients=%d steps=%d mode=%s wall=%.3fs steps/s=%.0f robot-steps/s=%.0f%n", n, steps, (obj ? "obj" : "raw") + (noStep ? "-nostep" : ""), secs, steps / secs, (double) n * steps / secs);
    }
}
