package robosim.environment.config;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.JsonDeserializer;
import com.fasterxml.jackson.databind.deser.DeserializationProblemHandler;
import java.io.IOException;
import java.util.Locale;
import robosim.protocol.Printable;

/**
 * What Jackson finds wrong while it binds an environment file, recorded as faults instead of thrown, so that reading
 * goes on and every such fault of the file is reported: an unknown element or attribute (skipped, whole) and a value
 * not of its attribute's type (read as absent, and marked on its element so no check calls it missing). Each is placed
 * where the parser stands when it finds it: an attribute's at the start of its element, an unknown element with
 * attributes (or none and no content) at its own start, one without attributes at what follows its start tag (its
 * text's end tag, the first element inside it). One per load.
 */
final class ProblemRecorder extends DeserializationProblemHandler {
    private final FileFaults faults;

    ProblemRecorder(FileFaults faults) {
        this.faults = faults;
    }

    @Override
    public boolean handleUnknownProperty(DeserializationContext context, JsonParser p, JsonDeserializer<?> deserializer,
            Object beanOrClass, String propertyName) throws IOException {
        faults.add(FilePosition.of(p.currentTokenLocation()), "unknown element or attribute '" + propertyName
                + "' (known here: " + deserializer.getKnownPropertyNames() + ")");
        p.skipChildren();
        return true;
    }

    @Override
    public Object handleWeirdStringValue(DeserializationContext context, Class<?> targetType, String value,
            String failureMessage) throws IOException {
        JsonParser p = context.getParser();
        String attribute = p.currentName();
        if (p.currentValue() instanceof FileElement element) {
            element.badValue(attribute);
        }
        faults.add(FilePosition.of(p.currentTokenLocation()), attribute + " value '" + Printable.of(value, 64)
                + "' is not a " + targetType.getSimpleName().toLowerCase(Locale.ROOT));
        return null;
    }
}
