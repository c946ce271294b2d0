package org.example.myrobot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import robosim.testkit.Pose;
import robosim.testkit.Simulation;
import robosim.testkit.World;

/** Explorer's behaviour, each in a small world of its own, run in this JVM by RoboSim's testkit. */
class ExplorerTest {
    @Test
    void inTheOpenItDrivesOneStepsWorthAheadEveryStep() {
        // a Scout drives 500 mm/s: 50 mm in a 100 ms step; its first step only looks (sleep(0))
        try (Simulation sim = Simulation.of(World.arena(10, 10).robot("e", "Scout", 2, 5, 0))
                .control("e", new Explorer()).start()) {
            sim.run(21);
            Pose p = sim.pose("e");
            assertEquals(3000, p.xMm(), 1, "x after 20 steps ahead: " + p);
            assertEquals(5000, p.yMm(), 1e-6);
            assertEquals(0, p.headingDeg(), 1e-6);
        }
    }

    @Test
    void itTurnsAwayFromAWallAheadBeforeTouchingIt() {
        // 3 m of open floor ahead of it, then the arena's wall
        try (Simulation sim = Simulation.of(World.arena(5, 5).robot("e", "ArRobot", 1, 2.5, 0))
                .control("e", new Explorer()).start()) {
            assertTrue(sim.runUntil(s -> Math.abs(s.pose("e").headingDeg()) > 20, 200), "it never turned");
            double wallGapMm = 5000 - sim.pose("e").xMm();
            assertTrue(wallGapMm > 400, "it turned only " + wallGapMm + " mm from the wall");
            sim.run(100);
            assertTrue(sim.contacts("e").isEmpty(), "it touched: " + sim.contacts("e"));
        }
    }

    @Test
    void inItsOwnWorldBothExplorersGetAround() {
        try (Simulation sim = Simulation.of(Path.of("my-world.xml")).start()) {
            Pose start1 = sim.pose("explorer1");
            Pose start2 = sim.pose("explorer2");
            sim.run(400); // 100 s of robot time
            assertTrue(sim.pose("explorer1").distanceMm(start1) > 1000, "explorer1 at " + sim.pose("explorer1"));
            assertTrue(sim.pose("explorer2").distanceMm(start2) > 1000, "explorer2 at " + sim.pose("explorer2"));
        }
    }
}
