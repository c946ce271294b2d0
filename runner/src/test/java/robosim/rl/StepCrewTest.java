package robosim.rl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(value = 5, unit = TimeUnit.MINUTES, threadMode = Timeout.ThreadMode.SEPARATE_THREAD) // (a hang fails, never blocks)
class StepCrewTest {
    @Test
    void everyShareOfEveryStepRunsOnceOnItsOwnThreadWhetherTheHelpersSpinOrPark() throws Exception {
        try (StepCrew crew = new StepCrew(2)) { // (as many threads as this machine kind's cores)
            AtomicIntegerArray runs = new AtomicIntegerArray(2);
            String[] names = new String[2];
            for (int k = 0; k < 1500; k++) {
                if (k % 500 == 499) { // (past the spin: the helper parks, and is woken)
                    LockSupport.parkNanos(3 * StepCrew.SPIN_NS);
                }
                int step = k;
                crew.run(share -> {
                    assertEquals(step, runs.getAndIncrement(share), "share " + share + " once a step");
                    names[share] = Thread.currentThread().getName();
                });
                for (int s = 0; s < 2; s++) {
                    assertEquals(k + 1, runs.get(s), "every share done when run returns");
                }
            }
            assertEquals(Thread.currentThread().getName(), names[0]);
            assertEquals("rl-worlds[1]", names[1]);
        }
    }

    @Test
    void aShareThatThrowsFailsTheStepAndTheCrewGoesOn() throws Exception {
        try (StepCrew crew = new StepCrew(2)) {
            IOException broken = new IOException("a recording could not be written");
            assertSame(broken, assertThrows(IOException.class, () -> crew.run(share -> {
                if (share == 1) {
                    throw broken;
                }
            })));
            boolean[] ran = new boolean[2];
            crew.run(share -> ran[share] = true);
            assertTrue(ran[0] && ran[1]);
        }
    }

    @Test
    void bothSharesFailingAreOneFailureWithTheOtherSuppressedInIt() {
        try (StepCrew crew = new StepCrew(2)) {
            IllegalArgumentException mine = assertThrows(IllegalArgumentException.class, () -> crew.run(share -> {
                throw share == 0 ? new IllegalArgumentException("share 0") : new IllegalStateException("share 1");
            }));
            assertEquals("share 1", mine.getSuppressed()[0].getMessage());
        }
    }

    @Test
    void aCrewClosedDuringAStepFinishesItAndThenTakesNoMore() throws Exception {
        StepCrew crew = new StepCrew(2);
        CountDownLatch inStep = new CountDownLatch(1);
        boolean[] ran = new boolean[2];
        Thread closer = new Thread(() -> {
            try {
                inStep.await();
            } catch (InterruptedException e) {
                return;
            }
            crew.close();
        }, "test-closer");
        closer.start();
        crew.run(share -> {
            if (share == 0) {
                inStep.countDown();
                closer.join();
            }
            ran[share] = true;
        });
        assertTrue(ran[0] && ran[1], "the step handed over was run whole");
        assertThrows(IllegalStateException.class, () -> crew.run(share -> { }));
    }
}
