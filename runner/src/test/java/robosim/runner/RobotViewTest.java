package robosim.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robosim.protocol.CommEvent;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotView;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.ViewerHello;

/**
 * The robot-specific viewer's stream: a viewer that watches a robot gets, after each update, that robot's
 * step as it saw it (its command, what it sent, what it was delivered); a name that is no robot is refused.
 */
class RobotViewTest {
    private static final long LONG_S = 120;

    @Test
    void aWatchingViewerGetsTheRobotsOwnStepAfterEachUpdate() throws Exception {
        CompletableFuture<SimulationEnd> refused = new CompletableFuture<>();
        InJvmSimulation live = new InJvmSimulation(InJvmSimulation.env("paper-benchmark.xml"))
                .sideline((env, ports) -> {
                    ViewerClient stranger = ViewerClient.connect("127.0.0.1", ports[1],
                            new ViewerHello(false, 0, "nobody\n"), LONG_S * 1000, null);
                    stranger.start(new ViewerStream());
                    refused.complete(stranger.awaitEnd(LONG_S, TimeUnit.SECONDS));
                })
                .run(300, false, Chatter::new);
        assertTrue(live.summary.completed(), live.summary.reason());
        assertEquals(-1, refused.get(LONG_S, TimeUnit.SECONDS).lastStep());
        assertEquals("it would watch \"nobody?\", which is not a robot of this simulation",
                refused.get().reason());

        String me = live.spec.robots().get(0).name();
        String next = live.spec.robots().get(1).name();
        String previous = live.spec.robots().get(live.spec.robots().size() - 1).name();
        List<PoseUpdate> updates = live.updates;
        assertEquals(updates.size(), live.views.size(), "a view after every update (a recording viewer misses none)");
        long sent = 0;
        long delivered = 0;
        boolean moved = false;
        boolean turned = false;
        for (int k = 0; k < updates.size(); k++) {
            RobotView v = live.views.get(k);
            assertEquals(updates.get(k).step(), v.step());
            assertEquals(v.step(), v.sinceStep(), "nothing merged for a recording viewer");
            assertEquals(0, v.robot());
            for (CommEvent m : v.sent()) {
                assertEquals(new CommEvent(me, next, Long.toString(sent)), m, "its outbox, in order, step " + v.step());
                sent++;
            }
            for (CommEvent m : v.delivered()) {
                assertEquals(previous, m.from());
                assertEquals(Long.toString(delivered), m.payload(), "its inbox, in order");
                delivered++;
            }
            assertTrue(v.moveMm() == 0 || v.moveMm() == 250, "its command: " + v.moveMm());
            assertTrue(v.turnDeg() == 0 || v.turnDeg() == 45, "its command: " + v.turnDeg());
            moved |= v.moveMm() == 250;
            turned |= v.turnDeg() == 45;
        }
        assertTrue(moved && turned, "Chatter moves and turns");
        Chatter first = (Chatter) live.controls.get(0);
        assertEquals(first.received, delivered, "every message the robot took is in its views");
        assertTrue(sent >= first.sent - 1 && sent <= first.sent, "what it sent: " + sent + " of " + first.sent);
    }
}
