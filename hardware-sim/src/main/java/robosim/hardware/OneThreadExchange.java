package robosim.hardware;

import java.io.IOException;

/**
 * {@code ONE_THREAD}, the default: the calling thread both sends each request and reads each response, in
 * turn, until the simulation is over.
 */
final class OneThreadExchange {
    private OneThreadExchange() {
    }

    /** Runs {@code sim}'s exchange until its simulation is over. */
    static void run(HardwareSimulator sim) throws IOException, InterruptedException {
        do {
            sim.send();
        } while (sim.receive());
    }
}
