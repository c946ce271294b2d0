package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * What a world holds besides its arena, obstacles and robots: its floor, its lights and its objects (each at its start
 * pose). Viewers get it in the snapshot; the Geometry process gets the objects. Written inline.
 */
public record Scenery(Floor floor, List<Light> lights, List<WorldObject> objects) {
    /** A plain floor, no lights, no objects. */
    public static final Scenery NONE = new Scenery(Floor.PLAIN, List.of(), List.of());

    public Scenery {
        java.util.Objects.requireNonNull(floor, "floor");
        lights = List.copyOf(lights);
        objects = List.copyOf(objects);
    }

    /** This scenery with its objects at other poses (each object's start pose replaced). */
    public Scenery withObjects(List<WorldObject> moved) {
        return new Scenery(floor, lights, moved);
    }

    void write(ObjectOutput out) throws IOException {
        floor.write(out);
        out.writeInt(lights.size());
        for (Light l : lights) {
            l.write(out);
        }
        writeObjects(out, objects);
    }

    static Scenery read(ObjectInput in) throws IOException {
        Floor floor = Floor.read(in);
        int n = Limits.checkCount("light count", in.readInt(), Limits.MAX_LIGHTS);
        List<Light> lights = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            lights.add(Light.read(in));
        }
        return new Scenery(floor, lights, readObjects(in));
    }

    static void writeObjects(ObjectOutput out, List<WorldObject> objects) throws IOException {
        out.writeInt(objects.size());
        for (WorldObject o : objects) {
            o.write(out);
        }
    }

    static List<WorldObject> readObjects(ObjectInput in) throws IOException {
        int n = Limits.checkCount("object count", in.readInt(), Limits.MAX_OBJECTS);
        List<WorldObject> objects = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            objects.add(WorldObject.read(in));
        }
        return List.copyOf(objects);
    }
}
