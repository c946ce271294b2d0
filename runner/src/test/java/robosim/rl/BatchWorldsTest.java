package robosim.rl;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;

class BatchWorldsTest {
    private static final VarHandle FLOAT = MethodHandles.byteArrayViewVarHandle(float[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle DOUBLE = MethodHandles.byteArrayViewVarHandle(double[].class,
            ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle LONG = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);

    static WorldSpec world() throws Exception {
        return new EnvironmentLoader().load(Path.of("src/test/resources/learning.xml"));
    }

    /** Every array of the batch, one after another. */
    private static byte[] arrays(BatchWorlds b) {
        byte[][] all = {b.steps(), b.sonar(), b.pose(), b.contact(), b.metrics(), b.messages()};
        return Arrays.stream(all).reduce(new byte[0], (x, y) -> {
            byte[] z = Arrays.copyOf(x, x.length + y.length);
            System.arraycopy(y, 0, z, x.length, y.length);
            return z;
        });
    }

    private static float[] randomActions(BatchWorlds b, SplittableRandom random) {
        float[] a = new float[b.count() * b.robots() * b.actionFields()];
        double[][] limits = b.limits();
        for (int i = 0; i < a.length; i++) {
            int field = i % b.actionFields();
            a[i] = field < 2 ? (float) random.nextDouble(-limits[(i / b.actionFields()) % b.robots()][field],
                    limits[(i / b.actionFields()) % b.robots()][field]) : (float) random.nextDouble(-1, 1);
        }
        return a;
    }

    @Test
    void theSameSeedsAndActionsGiveTheSameArraysBitForBitOnOneThreadOrTwo() throws Exception {
        WorldSpec spec = world();
        try (BatchWorlds one = new BatchWorlds(spec, 3, new BatchWorlds.Settings(2, 2, true, 0.5, 1));
                BatchWorlds two = new BatchWorlds(spec, 3, new BatchWorlds.Settings(2, 2, true, 0.5, 2));
                BatchWorlds other = new BatchWorlds(spec.withSeed(6), 3, new BatchWorlds.Settings(2, 2, true, 0.5, 2))) {
            SplittableRandom r1 = new SplittableRandom(9);
            SplittableRandom r2 = new SplittableRandom(9);
            boolean[] none = new boolean[3];
            long[] seeds = new long[3];
            assertArrayEquals(arrays(one), arrays(two));
            assertFalse(Arrays.equals(arrays(one), arrays(other)), "another seed, other headings");
            for (int k = 0; k < 150; k++) {
                one.step(randomActions(one, r1), none, seeds);
                two.step(randomActions(two, r2), none, seeds);
                assertArrayEquals(arrays(one), arrays(two), "step " + k);
            }
            assertEquals(1 + 150 * 2, (long) LONG.get(one.steps(), 16), "a settling step, then 2 time steps an action");
            assertTrue(metric(one, 0, "distance_m") > 0, "the robots went somewhere");
        }
    }

    @Test
    void anActionIsAVelocityHeldForTheRepeatAndTheSonarsOfEachTypeFillTheirRow() throws Exception {
        try (BatchWorlds b = new BatchWorlds(world(), 1, new BatchWorlds.Settings(5, 0, false, 0.5, 1))) {
            assertEquals(16, b.sonars(), "the most sonars of a robot of the world (a Scout's)");
            float[] a = new float[3 * 2];
            a[2] = 400; // b: 400 mm/s ahead (north, heading 90)
            a[5] = 30; // c: turns at 30 deg/s
            b.step(a, new boolean[1], new long[1]);
            assertEquals(1000 + 400 * 0.1 * 5, (float) FLOAT.get(b.pose(), 12 + 4), 1e-3, "b's y, mm");
            assertEquals(3000, (float) FLOAT.get(b.pose(), 12), 1e-3, "b's x, mm");
            assertEquals(45 + 30 * 0.1 * 5, (float) FLOAT.get(b.pose(), 24 + 8), 1e-3, "c's heading");
            for (int s = 8; s < 16; s++) {
                assertEquals(0f, (float) FLOAT.get(b.sonar(), s * 4), "beyond the ArRobot's 8 sonars");
            }
            for (int s = 0; s < 16; s++) {
                float range = (float) FLOAT.get(b.sonar(), (16 + s) * 4);
                assertTrue(range > 0 && range <= b.sonarMaxMm(1), "b's sonar " + s + ": " + range);
            }
            assertEquals(6L, (long) LONG.get(b.steps(), 0), "a settling step, then the action's 5");
        }
    }

    @Test
    void aMessageGoesToEveryRobotInRangeAndIsReadBackExactly() throws Exception {
        try (BatchWorlds b = new BatchWorlds(world(), 2, new BatchWorlds.Settings(1, 2, false, 0.5, 2))) {
            float[] a = new float[2 * 3 * 4];
            a[1 * 4 + 2] = 1.5f; // world 0, robot b's message
            a[1 * 4 + 3] = -0.25f;
            b.step(a, new boolean[2], new long[2]);
            int fieldsOfRow = 3 * 2;
            for (int to : new int[] {0, 2}) {
                int at = (to * fieldsOfRow + 1 * 2) * 4;
                assertEquals(1.5f, (float) FLOAT.get(b.messages(), at), "robot " + to + " heard b");
                assertEquals(-0.25f, (float) FLOAT.get(b.messages(), at + 4));
            }
            assertEquals(0f, (float) FLOAT.get(b.messages(), (1 * fieldsOfRow + 1 * 2) * 4), "not to itself");
            int world1 = 3 * fieldsOfRow * 4;
            for (int i = world1; i < b.messages().length; i += 4) {
                assertEquals(0f, (float) FLOAT.get(b.messages(), i), "world 1 sent nothing");
            }
            assertEquals(6.0, metric(b, 0, "messages_delivered"), "messages_delivered in world 0: each robot sends");
            b.step(new float[a.length], new boolean[2], new long[2]);
            assertEquals(0f, (float) FLOAT.get(b.messages(), (0 * fieldsOfRow + 1 * 2) * 4), "b sent zeros this time");
            b.step(a, new boolean[2], new long[2]);
            long world1Steps = (long) LONG.get(b.steps(), 8);
            b.step(null, new boolean[] {true, false}, new long[] {5, 0});
            for (int i = 0; i < 3 * fieldsOfRow * 4; i += 4) {
                assertEquals(0f, (float) FLOAT.get(b.messages(), i), "a new episode has heard nothing");
            }
            assertEquals(world1Steps, (long) LONG.get(b.steps(), 8), "without actions the worlds not reset stay as they are");
        }
    }

    @Test
    void aWorldThatIsResetBeginsAgainWhileTheOthersGoOn() throws Exception {
        try (BatchWorlds b = new BatchWorlds(world(), 2, new BatchWorlds.Settings(1, 0, false, 0.5, 2))) {
            float[] a = new float[2 * 3 * 2];
            Arrays.fill(a, 200);
            for (int k = 0; k < 10; k++) {
                b.step(a, new boolean[2], new long[2]);
            }
            b.step(a, new boolean[] {false, true}, new long[] {0, 5});
            assertEquals(12L, (long) LONG.get(b.steps(), 0));
            assertEquals(1L, (long) LONG.get(b.steps(), 8), "the settling step of a new episode");
            assertEquals(1000f, (float) FLOAT.get(b.pose(), 3 * 12), "world 1's a at its start again");
            assertEquals(0.0, metric(b, 1, "distance_m"), "world 1's distance from its new start");
            assertTrue(metric(b, 0, "distance_m") > 0);
        }
    }

    @Test
    void anEpisodeMetricIsComputedFromTheEpisodesRecordingAsASweepWould() throws Exception {
        for (String name : new String[] {"distance_m", "robosim.sweep.MeanFinalX"}) {
            try (BatchWorlds b = new BatchWorlds(world(), 2, new BatchWorlds.Settings(3, 0, false, 0.5, 2,
                    robosim.sweep.MetricChoice.parse(name)))) {
                float[] a = new float[2 * 3 * 2];
                SplittableRandom random = new SplittableRandom(2);
                for (int k = 0; k < 40; k++) {
                    for (int i = 0; i < a.length; i++) {
                        a[i] = (float) random.nextDouble(-200, 600);
                    }
                    b.step(a, new boolean[2], new long[2]);
                    if (k == 20) {
                        b.step(a, new boolean[] {false, true}, new long[] {0, 7});
                    }
                }
                for (int w = 0; w < 2; w++) {
                    double meanX = 0;
                    for (int i = 0; i < 3; i++) {
                        meanX += (float) FLOAT.get(b.pose(), (w * 3 + i) * 12) / 3000.0;
                    }
                    double expected = name.equals("distance_m") ? metric(b, w, "distance_m") : meanX;
                    assertEquals(expected, b.measure(w), name.equals("distance_m") ? 0 : 1e-6, name + ", world " + w);
                }
            }
        }
    }

    @Test
    void withSensorsEachRobotsReadingsLieInTheirSensorsColumns() throws Exception {
        WorldSpec spec = new EnvironmentLoader().load(Path.of("src/test/resources/sensors.xml"));
        try (BatchWorlds without = new BatchWorlds(spec, 1, new BatchWorlds.Settings(1, 0, false, 0.5, 1))) {
            assertEquals(0, without.sensorColumns().width(), "none unless asked");
        }
        try (BatchWorlds b = new BatchWorlds(spec, 2, new BatchWorlds.Settings(1, 0, false, 0.5, 1, null, true))) {
            SensorColumns columns = b.sensorColumns();
            assertEquals(java.util.List.of("laser", "bump", "heat"), columns.names(0));
            assertEquals(java.util.List.of(0, 181, 185), columns.of(0).stream().map(SensorColumns.Column::offset)
                    .toList(), "181 laser beams, 4 bump sides, 1 heat value");
            assertEquals(186, columns.width());
            b.step(new float[2 * 2], new boolean[2], new long[2]);
            for (int w = 0; w < 2; w++) {
                int row = w * 186 * 4;
                assertEquals(3000f, (float) FLOAT.get(b.readings(), row + 90 * 4), "the laser's middle beam: the wall");
                for (int side = 0; side < 4; side++) {
                    assertEquals(0f, (float) FLOAT.get(b.readings(), row + (181 + side) * 4), "touching nothing");
                }
                // the stove 0.5 m behind: 8 / (1 + 0.5^2)
                assertEquals(6.4f, (float) FLOAT.get(b.readings(), row + 185 * 4), 1e-5f, "the heat");
            }
        }
    }

    /** World {@code w}'s value of built-in metric {@code name}, where the registry's column order puts it. */
    private static double metric(BatchWorlds b, int w, String name) {
        int at = (w * BatchWorlds.METRICS.size() + BatchWorlds.METRICS.indexOf(name)) * 8;
        return (double) DOUBLE.get(b.metrics(), at);
    }
}
