/**
 * Environment files: the XML binding ({@link robosim.environment.config.EnvironmentFile}, read with
 * jackson-dataformat-xml) and the {@link robosim.environment.config.EnvironmentLoader} that checks it
 * and turns it into an immutable {@link robosim.environment.core.WorldSpec}. Used once, at start-up,
 * on the main thread.
 */
package robosim.environment.config;
