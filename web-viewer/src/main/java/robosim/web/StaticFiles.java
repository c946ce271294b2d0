package robosim.web;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Map;

/**
 * The page's files, read from the jar once: {@code /} (index.html), {@code /viewer.js}, {@code /view3d.js},
 * {@code /robot.js}, {@code /scenery.js} and three.js (from its webjar). Nothing else is served: no path from a request ever reaches a file name.
 */
final class StaticFiles {
    private static final String THREE = "META-INF/resources/webjars/three/0.181.1/build/";

    record File(byte[] bytes, String contentType) {
    }

    private final Map<String, File> files;

    StaticFiles() {
        files = Map.of(
                "/", load("robosim/web/index.html", "text/html; charset=utf-8"),
                "/viewer.js", load("robosim/web/viewer.js", "text/javascript; charset=utf-8"),
                "/view3d.js", load("robosim/web/view3d.js", "text/javascript; charset=utf-8"),
                "/robot.js", load("robosim/web/robot.js", "text/javascript; charset=utf-8"),
                "/scenery.js", load("robosim/web/scenery.js", "text/javascript; charset=utf-8"),
                "/three/three.module.min.js", load(THREE + "three.module.min.js", "text/javascript; charset=utf-8"),
                "/three/three.core.min.js", load(THREE + "three.core.min.js", "text/javascript; charset=utf-8"));
    }

    /** The file at {@code path} (without its query), or null. */
    File get(String path) {
        int q = path.indexOf('?');
        return files.get(q < 0 ? path : path.substring(0, q));
    }

    private static File load(String resource, String type) {
        try (InputStream in = StaticFiles.class.getClassLoader().getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException("the web viewer's " + resource + " is not in the jar");
            }
            return new File(in.readAllBytes(), type);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
