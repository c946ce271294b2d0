package robosim.hardware;

import java.util.Set;

/** The parameters a robot's control code asked for ({@code Robot.parameter}) and those it was given, by name. */
public record ParameterAsks(Set<String> asked, Set<String> given) {
    /** Nothing asked, nothing given (control code not started). */
    public static final ParameterAsks NONE = new ParameterAsks(Set.of(), Set.of());

    public ParameterAsks {
        asked = Set.copyOf(asked);
        given = Set.copyOf(given);
    }
}
