package robosim.web;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import robosim.protocol.Traces;

/** The page's feed of what loop functions drew: a piece as the page pieces it together (viewer.js, draw). */
class WebJsonTest {
    @Test
    void aPieceOfADrawingSaysWhereItFollowsOn() {
        Traces.Log drawing = new Traces.Log();
        drawing.add("fb0", 1000.04, 2000, 0xFF0000);
        drawing.since();
        drawing.add("fb0", 1050, 2000, 0xFF0000);
        drawing.add("fb1", 3000, 4000.25, 0x00FF00);
        assertEquals("{\"type\":\"traces\",\"fresh\":false,\"firstTrace\":1,\"names\":[\"fb1\"],"
                + "\"colours\":[\"#00ff00\"],\"firstPoint\":1,\"points\":[0,1050.0,2000.0,1,3000.0,4000.3]}",
                WebJson.traces(drawing.since()));
        assertEquals("{\"type\":\"traces\",\"fresh\":true,\"firstTrace\":0,\"names\":[\"fb0\",\"fb1\"],"
                + "\"colours\":[\"#ff0000\",\"#00ff00\"],\"firstPoint\":0,\"points\":[0,1000.0,2000.0,0,1050.0,"
                + "2000.0,1,3000.0,4000.3]}", WebJson.traces(drawing.whole()));
    }
}
