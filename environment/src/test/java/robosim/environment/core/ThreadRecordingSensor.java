package robosim.environment.core;

import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import robosim.devices.RobotSensor;
import robosim.devices.SensorContext;
import robosim.devices.SensorInfo;
import robosim.devices.SensorValues;

/** A sensor that exists only in the tests: it notes the name of every thread the core reads it on. */
public final class ThreadRecordingSensor extends RobotSensor {
    /** Every thread a step's sense phase ran on, in any test of this JVM. */
    public static final Set<String> THREADS = ConcurrentHashMap.newKeySet();

    public ThreadRecordingSensor() {
        super(new SensorInfo("threads", "notes its thread", List.of(), "one value, 0", "1", false,
                SensorInfo.Display.VALUES));
    }

    @Override
    public SensorValues values() {
        return new SensorValues(1, 0, 0, "1");
    }

    @Override
    public double[] generateSensorResponse(SensorContext context) {
        THREADS.add(Thread.currentThread().getName());
        return new double[] {0};
    }
}
