package robosim.rl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;

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
}
