package robosim.environment.metrics;

import robosim.protocol.Arena;

/**
 * A run as its metrics begin it: its arena, the side of the cells an area is counted in ({@code areaCellM}, m), and
 * the world before its first step ({@code start}: every robot at its start pose, none took part).
 */
public record RunStart(Arena arena, double areaCellM, StepView start) {
}
