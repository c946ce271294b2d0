package robosim.environment.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.InMemoryLink;

/**
 * What a coordinator design allows is held to it once, where the Environment is configured: the settings of a
 * design that cannot serve them are refused as they are built, saying why, and a design says which transports it
 * serves.
 */
class SettingsTest {
    private static final InMemoryLink.Starter STARTER = new InMemoryLink.Starter() {
        @Override
        public InMemoryLink.Robot start(String name, String type, String controlClass, InMemoryLink.Environment env) {
            throw new AssertionError("never started");
        }

        @Override
        public InMemoryLink.ControlEnd awaitControlCode(long ms) {
            return InMemoryLink.ControlEnd.CLEAN;
        }
    };

    @Test
    void theSequentialLoopRefusesALossPolicyThatHoldsRobotsAndRobotsInThisJvm() {
        IllegalArgumentException hold = assertThrows(IllegalArgumentException.class, () -> Settings.builder()
                .design(CoordinatorDesign.SEQUENTIAL).onRobotLoss(RobotLoss.HOLD).build());
        assertEquals("--on-robot-loss HOLD needs the THREADS or TWO_THREADS coordinator: the SEQUENTIAL loop reads a "
                + "fixed list of robots", hold.getMessage());
        IllegalArgumentException inMemory = assertThrows(IllegalArgumentException.class, () -> Settings.builder()
                .design(CoordinatorDesign.SEQUENTIAL).robotsInThisJvm(STARTER).build());
        assertEquals("--one-jvm runs its robots in memory; --coordinator SEQUENTIAL reads a socket per robot (use "
                + "THREADS or TWO_THREADS, which serve robots that join over the robot port)", inMemory.getMessage());
        assertEquals(STARTER, Settings.builder().design(CoordinatorDesign.TWO_THREADS).onRobotLoss(RobotLoss.WAIT)
                .robotsInThisJvm(STARTER).build().robotsInThisJvm());
    }

    @Test
    void aDesignSaysWhichTransportsItServes() {
        for (CoordinatorDesign d : CoordinatorDesign.values()) {
            assertNull(d.refuses(Transport.SOCKET), d + " serves a socket per robot");
            assertEquals(d == CoordinatorDesign.SEQUENTIAL, d.refuses(Transport.SHARED) != null, d + ", shared");
            assertEquals(d == CoordinatorDesign.SEQUENTIAL, d.refuses(Transport.IN_MEMORY) != null, d + ", in memory");
            assertEquals(d == CoordinatorDesign.SEQUENTIAL, d.refusesJoins() != null, d + ", joins");
        }
    }
}
