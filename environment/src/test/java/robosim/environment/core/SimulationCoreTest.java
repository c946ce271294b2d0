package robosim.environment.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.Arena;
import robosim.protocol.CommEvent;
import robosim.protocol.ObstacleShape;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotProperties;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/** The core without sockets: routing, limits, contact names, determinism. */
class SimulationCoreTest {
    private static final WorldSpec SPEC = new WorldSpec("mem", "t", 500, 1, new Arena(0, 0, 10_000, 10_000),
            List.of(ObstacleShape.rectangle("wall", 6000, 0, 100, 10_000)),
            List.of(new WorldSpec.RobotSpec("a", "ArRobot", "", 1000, 1000, 0),
                    new WorldSpec.RobotSpec("b", "ArRobot", "", 1000, 3000, 0),
                    new WorldSpec.RobotSpec("c", "Scout", "", 5000, 5000, 0)));
    private static final List<RobotProperties> PROPS = List.of(robosim.devices.RobotTypes.properties("ArRobot"), robosim.devices.RobotTypes.properties("ArRobot"),
            robosim.devices.RobotTypes.properties("Scout"));

    private static StepRequest req(long k, double move, double turn, CommEvent... messages) {
        return new StepRequest(k, move, turn, true, List.of(messages));
    }

    @Test
    void messagesAreDeliveredInTheSameStepInSenderAndSendOrder() throws Exception {
        InProcessSteps core = InProcessSteps.of(SPEC, PROPS);
        core.step(0, new StepRequest[] {
            req(0, 0, 0, new CommEvent("", "c", "a1"), new CommEvent("", "c", "a2")),
            req(0, 0, 0, new CommEvent("", "c", "b1"), new CommEvent("", "nobody", "x")),
            req(0, 0, 0)});
        List<CommEvent> inbox = core.response(2).inbox();
        assertEquals(List.of("a1", "a2", "b1"), inbox.stream().map(CommEvent::payload).toList());
        assertEquals("a", inbox.get(0).from());
        assertEquals(List.of("message to nobody not delivered: no robot of that name"), core.response(1).notices());
        assertEquals(3, core.messagesDelivered());
        assertEquals(1, core.messagesUndeliverable());
        core.step(1, new StepRequest[] {req(1, 0, 0), req(1, 0, 0), req(1, 0, 0)});
        assertTrue(core.response(2).inbox().isEmpty(), "delivered exactly once");
    }

    @Test
    void theTallyCountsAStepAsItWentOutNotAResponseWithheld() throws Exception {
        SimulationCore core = new SimulationCore(SPEC, PROPS, 0.5);
        InProcessGeometry geometry = new InProcessGeometry(core.map().geometryWorld());
        core.step(0, new StepRequest[] {req(0, 0, 0), req(0, 0, 0, new CommEvent("", "a", "to a")), req(0, 0, 0)},
                geometry);
        core.withhold(0); // (a left during the step: its message goes back to its inbox)
        core.tally(robot -> true); // (as the Run's: a robot leaving at the step's end took part in it)
        int delivered = robosim.environment.metrics.Metrics.names().indexOf("messages_delivered");
        assertEquals(0, core.metrics().value(delivered), "nothing went out to a");
        core.step(1, new StepRequest[] {req(1, 0, 0), req(1, 0, 0), req(1, 0, 0)}, geometry);
        core.tally();
        assertEquals(1, core.metrics().value(delivered), "a gets it the next step, counted once");
    }

    @Test
    void aBroadcastReachesEveryOtherRobotInSenderOrder() throws Exception {
        InProcessSteps core = InProcessSteps.of(SPEC, PROPS);
        core.step(0, new StepRequest[] {req(0, 0, 0, new CommEvent("", "*", "hello all")),
            req(0, 0, 0, new CommEvent("", "c", "b to c")), req(0, 0, 0)});
        assertEquals(List.of(), core.response(0).inbox(), "not to the sender itself");
        assertEquals(List.of(new CommEvent("a", "b", "hello all")), core.response(1).inbox());
        assertEquals(List.of(new CommEvent("a", "c", "hello all"), new CommEvent("b", "c", "b to c")),
                core.response(2).inbox());
        assertEquals(3, core.messagesDelivered());
    }

    @Test
    void outOfRangeMessagesAreDroppedAndCountedAndOversizedOnesRefusedWithANotice() throws Exception {
        // a at (1, 1) m, b at (1, 3) m: 2 m apart; c at (5, 5) m: 5.66 m from a. Range 2.5 m, limit 10 bytes.
        WorldSpec limited = new WorldSpec("mem", "t", 500, 1, SPEC.arena(), SPEC.obstacles(), SPEC.robots(), 2500, 10);
        InProcessSteps core = InProcessSteps.of(limited, PROPS);
        core.step(0, new StepRequest[] {
            req(0, 0, 0, new CommEvent("", "b", "near"), new CommEvent("", "c", "far"),
                    new CommEvent("", "b", "eleven char")),
            req(0, 0, 0, new CommEvent("", "*", "all")), req(0, 0, 0)});
        assertEquals(List.of(new CommEvent("a", "b", "near")), core.response(1).inbox());
        assertEquals(List.of(new CommEvent("b", "a", "all")), core.response(0).inbox(), "c is 4.47 m from b");
        assertEquals(List.of(), core.response(2).inbox());
        assertEquals(List.of("message to b not sent: 11 bytes is more than the limit of 10"),
                core.response(0).notices());
        assertEquals(2, core.messagesDelivered());
        assertEquals(2, core.messagesOutOfRange(), "a to c, and b's broadcast to c");
        assertEquals(1, core.messagesUndeliverable());
    }

    @Test
    void movesAreAppliedWithTheSpeedLimitAndContactsAreNamed() throws Exception {
        InProcessSteps core = InProcessSteps.of(SPEC, PROPS);
        // ArRobot max 1000 mm/s: 500 mm per 500 ms step
        core.step(0, new StepRequest[] {req(0, 800, 0), req(0, 250, 90), req(0, 500, 0)});
        StepResponse a = core.response(0);
        assertEquals(500, a.movedMm());
        assertEquals(1500, a.xMm());
        assertTrue(a.notices().get(0).startsWith("move of 800.0 mm limited to 500.0 mm"), a.notices().toString());
        StepResponse b = core.response(1);
        assertEquals(90, b.headingDeg());
        assertEquals(3250, b.yMm(), 1e-9);
        assertEquals(8, a.sonarMm().length);
        assertEquals(16, core.response(2).sonarMm().length);
        // robot c is 5000 - 190 = 4810 from... its rim at 5190, the wall face at 6000: drive into it
        core.step(1, new StepRequest[] {req(1, 0, 0), req(1, 0, 0), req(1, 500, 0)});
        core.step(2, new StepRequest[] {req(2, 0, 0), req(2, 0, 0), req(2, 500, 0)});
        StepResponse c = core.response(2);
        assertEquals("wall", c.contact());
        assertEquals(6000 - 190, c.xMm(), 1e-5);
    }

    @Test
    void aRequestForTheWrongStepOrWithNaNIsAProtocolError() {
        InProcessSteps core = InProcessSteps.of(SPEC, PROPS);
        assertThrows(ProtocolException.class, () -> core.step(0, new StepRequest[] {req(5, 0, 0), null, null}));
        assertThrows(ProtocolException.class,
                () -> core.step(0, new StepRequest[] {req(0, Double.NaN, 0), null, null}));
    }

    @Test
    void sameRequestsGiveTheSamePosesBitForBit() throws Exception {
        double[][] first = run();
        double[][] second = run();
        for (int i = 0; i < first.length; i++) {
            assertArrayEquals(first[i], second[i]);
        }
    }

    private static double[][] run() throws Exception {
        InProcessSteps core = InProcessSteps.of(SPEC, PROPS);
        java.util.Random random = new java.util.Random(7);
        for (long k = 0; k < 500; k++) {
            StepRequest[] q = new StepRequest[3];
            for (int i = 0; i < 3; i++) {
                q[i] = req(k, random.nextDouble() * 500 - 100, random.nextDouble() * 60 - 30);
            }
            core.step(k, q);
        }
        double[][] poses = new double[3][];
        for (int i = 0; i < 3; i++) {
            StepResponse r = core.response(i);
            poses[i] = new double[] {r.xMm(), r.yMm(), r.headingDeg()};
        }
        return poses;
    }

    /** Loop functions whose init paints the floor, switches the light off and takes the crate out. */
    public static final class Tidies implements robosim.loop.LoopFunctions {
        @Override
        public void init(robosim.loop.Experiment world) {
            world.paintDisc(500, 500, 200, 0x000000);
            world.switchLight(0, false);
            world.removeObject(0);
        }
    }

    @Test
    void theWorldBeforeStepZeroIsAsTheLoopFunctionsInitLeftIt(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        java.nio.file.Path file = dir.resolve("tidy.xml");
        java.nio.file.Files.writeString(file, """
                <environment name="tidy" timeStepMs="100">
                  <loopFunctions class="robosim.environment.core.SimulationCoreTest$Tidies"/>
                  <arena width="3" height="2"/>
                  <floor colour="white"/>
                  <lights><light name="lamp" x="1.5" y="1" height="0.5" intensity="3" colour="yellow"/></lights>
                  <objects><box name="crate" x="2.5" y="0.5" width="0.2" depth="0.2" height="0.1"/></objects>
                  <robots><robot name="fb" type="foot-bot" x="1" y="1" heading="0"/></robots>
                </environment>
                """);
        WorldSpec spec = new robosim.environment.config.EnvironmentLoader().load(file);
        SimulationCore core = new SimulationCore(spec, List.of(robosim.devices.RobotTypes.properties("foot-bot")));
        core.startExperiment(dir, null);
        // (a viewer joining before step 0, and a recording's first snapshot, start from this)
        robosim.protocol.PoseUpdate start = core.startUpdate().posesOnly();
        assertEquals(1, start.paint().size(), "the floor as init painted it");
        assertArrayEquals(new boolean[] {false}, start.lightsOn(), "the light as init switched it");
        assertArrayEquals(new int[] {0}, start.objectsGone(), "the crate init took out");
    }
}
