package robosim.environment.replay;

import robosim.environment.run.RunStatus;

/**
 * Where a replay stands, as its {@code status} request tells (its state named as a live run's): {@code step} is the step shown,
 * {@code firstStep} and {@code lastStep} the recording's, as displays number them ({@link robosim.protocol.StepNumbers}:
 * steps completed; 0 before the first), {@code stepsPerSecond} the pace its speed sets.
 */
public record ReplayStatus(RunStatus.State state, long step, long firstStep, long lastStep, int steps, double speed,
        int viewers, boolean atEnd, double stepsPerSecond) {
}
