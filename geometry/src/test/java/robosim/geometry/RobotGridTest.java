package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Envelope;

/** The grid only narrows a search: every robot whose disc meets a query box is in a selected cell. */
class RobotGridTest {
    @Test
    void everyRobotNearAQueryIsFoundAfterRandomMoves() {
        Random random = new Random(7);
        for (int round = 0; round < 50; round++) {
            int n = 1 + random.nextInt(300);
            double r = 100 + random.nextDouble() * 300;
            double side = 1000 + random.nextDouble() * 60_000;
            double[] x = new double[n];
            double[] y = new double[n];
            for (int i = 0; i < n; i++) {
                x[i] = random.nextDouble() * side - side / 3;
                y[i] = random.nextDouble() * side - side / 3;
            }
            RobotGrid grid = new RobotGrid(n, r);
            grid.rebuild(x, y);
            // moves, some far outside the box the grid was sized for
            for (int m = 0; m < n; m++) {
                int i = random.nextInt(n);
                double reach = random.nextBoolean() ? 500 : 3 * side;
                x[i] += (random.nextDouble() - 0.5) * reach;
                y[i] += (random.nextDouble() - 0.5) * reach;
                grid.moved(i, x[i], y[i]);
            }
            for (int q = 0; q < 200; q++) {
                double cx = random.nextDouble() * 3 * side - side;
                double cy = random.nextDouble() * 3 * side - side;
                double w = random.nextDouble() * 10_000;
                Envelope area = new Envelope(cx, cx + w, cy, cy + random.nextDouble() * 10_000);
                Set<Integer> found = new HashSet<>();
                RobotGrid.Cursor cells = grid.new Cursor();
                cells.select(area);
                for (int c = cells.nextCell(); c >= 0; c = cells.nextCell()) {
                    for (int j = grid.first(c); j >= 0; j = grid.next(j)) {
                        assertTrue(found.add(j), "robot " + j + " listed twice");
                    }
                }
                for (int j = 0; j < n; j++) {
                    boolean overlaps = x[j] + r >= area.getMinX() && x[j] - r <= area.getMaxX()
                            && y[j] + r >= area.getMinY() && y[j] - r <= area.getMaxY();
                    if (overlaps) {
                        assertTrue(found.contains(j), "round " + round + ": robot " + j + " at " + x[j] + ","
                                + y[j] + " missed by a query of " + area);
                    }
                }
            }
        }
    }
}
