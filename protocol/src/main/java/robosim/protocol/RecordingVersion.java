package robosim.protocol;

import java.io.ObjectInput;

/**
 * What an input stream knows of the recording it reads, for the messages whose form changed between recording
 * versions: a stream of a connection, like any input that is not one of these, reads the current form. (Its own type,
 * so that a message that asks depends on nothing that names the messages.)
 */
interface RecordingVersion {
    /** The recording version before worlds had scenery, objects and LEDs: its snapshots and steps end without them. */
    byte WITHOUT_SCENE = 4;

    /** The recording version before worlds had loop functions: its steps end without what they painted and reported. */
    byte WITHOUT_EXPERIMENT = 5;

    /** The recording version before loop functions drew over the world: its steps end without their traces. */
    byte WITHOUT_TRACES = 6;

    /** The recording version this stream reads a frame of. */
    int recordingVersion();

    /** True unless {@code in} reads a recording of version {@link #WITHOUT_SCENE} or older. */
    static boolean withScene(ObjectInput in) {
        return !(in instanceof RecordingVersion v) || v.recordingVersion() > WITHOUT_SCENE;
    }

    /** True unless {@code in} reads a recording of version {@link #WITHOUT_EXPERIMENT} or older. */
    static boolean withExperiment(ObjectInput in) {
        return !(in instanceof RecordingVersion v) || v.recordingVersion() > WITHOUT_EXPERIMENT;
    }

    /** True unless {@code in} reads a recording of version {@link #WITHOUT_TRACES} or older. */
    static boolean withTraces(ObjectInput in) {
        return !(in instanceof RecordingVersion v) || v.recordingVersion() > WITHOUT_TRACES;
    }
}
