package robosim.environment.config;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.BeanDescription;
import com.fasterxml.jackson.databind.DeserializationConfig;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.JsonDeserializer;
import com.fasterxml.jackson.databind.deser.BeanDeserializerModifier;
import com.fasterxml.jackson.databind.deser.std.DelegatingDeserializer;
import com.fasterxml.jackson.dataformat.xml.JacksonXmlModule;
import java.io.IOException;

/**
 * jackson-dataformat-xml's module, and one thing more: every {@link FileElement} it reads gets the position where
 * its start tag begins (the parser's at the element's start, before any attribute or child is read), for the
 * faults found in it later.
 */
final class PositionedXmlModule extends JacksonXmlModule {
    @Override
    public void setupModule(SetupContext context) {
        // Jackson calls the modifier added last first: added before the XML module's own, this one wraps the
        // deserializer that one made (which must see the bean deserializer itself to read unwrapped lists).
        context.addBeanDeserializerModifier(new BeanDeserializerModifier() {
            @Override
            public JsonDeserializer<?> modifyDeserializer(DeserializationConfig config, BeanDescription bean,
                    JsonDeserializer<?> deserializer) {
                return FileElement.class.isAssignableFrom(bean.getBeanClass()) ? new Positioned(deserializer)
                        : deserializer;
            }
        });
        super.setupModule(context);
    }

    /** An element's deserializer that sets where the element starts on what it read. */
    private static final class Positioned extends DelegatingDeserializer {
        Positioned(JsonDeserializer<?> element) {
            super(element);
        }

        @Override
        protected JsonDeserializer<?> newDelegatingInstance(JsonDeserializer<?> element) {
            return new Positioned(element);
        }

        @Override
        public Object deserialize(JsonParser p, DeserializationContext context) throws IOException {
            FilePosition at = FilePosition.of(p.currentTokenLocation());
            Object read = super.deserialize(p, context);
            if (read instanceof FileElement element) {
                element.at = at;
            }
            return read;
        }
    }
}
