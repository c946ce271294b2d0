package robosim.environment.config;

import com.fasterxml.jackson.core.JsonLocation;

/** Where something starts in an environment file's text: its line and column, both counted from 1. */
record FilePosition(int line, int column) {
    /** Jackson's location, or null when it has none. */
    static FilePosition of(JsonLocation location) {
        return location == null || location.getLineNr() < 1 ? null
                : new FilePosition(location.getLineNr(), location.getColumnNr());
    }

    /** {@code LINE:COLUMN}, as a fault's line shows it. */
    @Override
    public String toString() {
        return line + ":" + column;
    }
}
