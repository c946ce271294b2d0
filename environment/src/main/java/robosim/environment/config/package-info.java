/**
 * Environment files: the XML binding ({@link robosim.environment.config.EnvironmentFile}, read with
 * jackson-dataformat-xml) and the {@link robosim.environment.config.EnvironmentLoader} that checks it
 * and turns it into an immutable {@link robosim.environment.core.WorldSpec}. A file's faults are gathered in one
 * {@link robosim.environment.config.FileFaults} per load, each at the {@link robosim.environment.config.FilePosition}
 * where its element starts: {@link robosim.environment.config.PositionedXmlModule} sets that on each
 * {@link robosim.environment.config.FileElement} as it is read, and
 * {@link robosim.environment.config.ProblemRecorder} records what Jackson finds wrong meanwhile. Used at start-up
 * and by the control port's {@code load}, on whichever thread calls; a load shares nothing with another but the
 * immutable Jackson reader.
 */
package robosim.environment.config;
