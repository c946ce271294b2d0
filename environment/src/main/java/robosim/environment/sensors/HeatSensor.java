package robosim.environment.sensors;

import robosim.environment.core.WorldSpec.HeatSource;

/**
 * Heat at the robot's centre: the sum, over every heat source the robot can see (no obstacle on
 * the straight line between them), of {@code intensity / (1 + d^2)} with d the distance in metres.
 * At the source a reading equals the intensity; at 1 m it is half; behind a wall it is zero.
 */
public final class HeatSensor extends RobotSensor {
    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double heat = 0;
        for (HeatSource h : c.heatSources()) {
            if (c.clearTo(h.xMm(), h.yMm())) {
                double dM = Math.hypot(h.xMm() - c.xMm(), h.yMm() - c.yMm()) / 1000;
                heat += h.intensity() / (1 + dM * dM);
            }
        }
        return new double[] {heat};
    }
}
