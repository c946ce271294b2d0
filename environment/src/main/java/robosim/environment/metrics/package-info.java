/**
 * The built-in metrics of a run, one class each ({@link robosim.environment.metrics.StepMetric}: its
 * {@link robosim.environment.metrics.MetricInfo} and how it counts, step by step), found by the registry
 * {@link robosim.environment.metrics.Metrics}, and a run's {@link robosim.environment.metrics.MetricTally}. A metric
 * sees a step through a {@link robosim.environment.metrics.StepView}, which the simulation core offers live and a
 * recording offers read back, so both give the same values. Plain objects, called on the thread that steps the run.
 */
package robosim.environment.metrics;
