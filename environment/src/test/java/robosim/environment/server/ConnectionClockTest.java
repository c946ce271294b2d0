package robosim.environment.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** One connection's clocks, judged at chosen moments: no sleeps, no threads. */
class ConnectionClockTest {
    private static final long LATER = TimeUnit.HOURS.toNanos(1);

    @Test
    void aHelloNotInByTheHandshakeDeadlineIsCutOffOnceAndItsHandshakeCannotEndAfter() {
        ConnectionClock c = new ConnectionClock(500, 10_000);
        assertNull(c.cutOffIfLate(System.nanoTime()), "in time so far");
        assertEquals("no hello within 500 ms", c.cutOffIfLate(System.nanoTime() + LATER));
        assertNull(c.cutOffIfLate(System.nanoTime() + LATER), "cut off once");
        assertFalse(c.handshakeOver(), "the deadline came first");
        assertEquals("no hello within 500 ms", c.cutOffReason());
    }

    @Test
    void aHandshakeOverInTimeIsNeverCutOffForItButAWriteNotTakenIs() {
        ConnectionClock c = new ConnectionClock(500, 10_000);
        assertTrue(c.handshakeOver());
        assertNull(c.cutOffIfLate(System.nanoTime() + LATER), "no deadline once the hello is in, no write under way");
        c.writing();
        c.written();
        assertNull(c.cutOffIfLate(System.nanoTime() + LATER), "a write taken");
        c.writing();
        assertNull(c.cutOffIfLate(System.nanoTime()), "a write under way, not late yet");
        assertEquals("did not take a write within 10000 ms", c.cutOffIfLate(System.nanoTime() + LATER));
        assertEquals("did not take a write within 10000 ms", c.cutOffReason());
    }

    @Test
    void noLimitsMeansNeverLate() {
        ConnectionClock c = new ConnectionClock(0, 0);
        c.writing();
        assertNull(c.cutOffIfLate(System.nanoTime() + LATER));
        assertTrue(c.handshakeOver());
    }
}
