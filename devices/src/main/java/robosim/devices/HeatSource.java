package robosim.devices;

/** A source of heat for heat sensors: position (mm) and intensity (the reading at the source). */
public record HeatSource(String name, double xMm, double yMm, double intensity) {
}
