package robosim.devices;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** A proximity reading turned back into a distance: each model's law, as its class says it, turned round. */
class ProximitySensorTest {
    @Test
    void aReadingGivesBackTheDistanceItWasReadAt() {
        for (int mm = 10; mm <= 100; mm += 5) {
            double m = mm / 1000.0;
            double footBot = 0.0100527 / (m + 0.000163144);
            assertEquals(m, ProximitySensor.distanceM("foot-bot", footBot), 1e-12, "foot-bot at " + m);
        }
        for (int tenths = 0; tenths <= 470; tenths += 25) { // (the law falls to 0 at 0.0479 m: within, every reading)
            double m = tenths / 10000.0;
            double ePuck = Math.min(1, 298.701 * m * m - 36.8961 * m + 1.08212);
            double back = ProximitySensor.distanceM("e-puck", ePuck);
            assertEquals(ePuck, Math.min(1, 298.701 * back * back - 36.8961 * back + 1.08212), 1e-9, "e-puck at " + m);
        }
    }

    @Test
    void nothingInRangeIsInfinitelyFarAndContactIsTheLawsNearest() {
        assertEquals(Double.POSITIVE_INFINITY, ProximitySensor.distanceM("foot-bot", 0));
        assertEquals(Double.POSITIVE_INFINITY, ProximitySensor.distanceM("e-puck", 0));
        assertEquals(0.009889556, ProximitySensor.distanceM("foot-bot", 1), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> ProximitySensor.distanceM("kilobot", 0.5));
    }
}
