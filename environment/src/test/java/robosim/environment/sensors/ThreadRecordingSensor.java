package robosim.environment.sensors;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/** A plug-in sensor that exists only in the tests: it notes the name of every thread the core reads it on. */
public final class ThreadRecordingSensor extends RobotSensor {
    /** Every thread a step's sense phase ran on, in any test of this JVM. */
    public static final Set<String> THREADS = ConcurrentHashMap.newKeySet();

    @Override
    public double[] generateSensorResponse(SensorContext context) {
        THREADS.add(Thread.currentThread().getName());
        return new double[] {0};
    }
}
