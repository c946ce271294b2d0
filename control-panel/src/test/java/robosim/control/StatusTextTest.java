package robosim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;

/** The Control Panel's status text: steps/s only while running; fields shown as the Environment said. */
class StatusTextTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    private static JsonNode status(String json) throws Exception {
        return JSON.readTree(json.replace('\'', '"'));
    }

    @Test
    void stepsPerSecondOnlyWhileRunning() throws Exception {
        assertEquals("RUNNING   step 120   2.0 steps/s",
                StatusText.headline(status("{'state':'RUNNING','step':120,'steps_per_s':2.0}")));
        assertEquals("PAUSED   step 120", StatusText.headline(status("{'state':'PAUSED','step':120,'steps_per_s':0}")));
        assertEquals("ENDED   step 300", StatusText.headline(status("{'state':'ENDED','step':300,'steps_per_s':0}")));
    }

    @Test
    void detailsShowGeometryAndWhoLeft() throws Exception {
        assertEquals("file:      remote.xml\nrobots:    rc1, rc2\nconnected: rc1\nleft:      rc2\ngeometry:  in-process",
                StatusText.details(status("{'file':'remote.xml','robots':['rc1','rc2'],'connected':['rc1'],"
                        + "'left':['rc2'],'geometry':'in-process'}")));
        assertEquals("file:      remote.xml\nrobots:    rc1\nconnected: -\nleft:      rc1\ngeometry:  none\n"
                + "ended:     stopped from the control port",
                StatusText.details(status("{'file':'remote.xml','robots':['rc1'],'connected':[],'left':['rc1'],"
                        + "'geometry':'none','reason':'stopped from the control port'}")));
    }

    @Test
    void robotsShowTheirStateAndOnlyThoseInTheRunMayBeRemoved() throws Exception {
        JsonNode s = status("{'file':'ring.xml','robots':['a','b','c','d'],'connected':['a'],'left':['b','c'],"
                + "'geometry':'in-process','robot_states':[{'name':'a','state':'running'},"
                + "{'name':'b','state':'held','since':1001},{'name':'c','state':'gone','since':40},"
                + "{'name':'d\\u0007','state':'returning','since':7},{'name':'e','state':'added'}]}");
        assertEquals("file:      ring.xml\nrobots:    a, b held since 1001, c gone since 40, d? returning since 7, e added\n"
                + "connected: a\nleft:      b, c\ngeometry:  in-process", StatusText.details(s));
        assertEquals(java.util.List.of("a", "b", "d?", "e"), StatusText.removable(s));
    }

    @Test
    void theAddFormMakesOneRequestLineOrSaysWhichFieldIsWrong() {
        assertEquals("add scout-9 Scout 1.5 2.0 90.0 robosim.examples.Wander",
                AddRobotForm.request(" scout-9 ", "Scout", "1.5", " 2", "90", "robosim.examples.Wander "));
        assertEquals("add r Scout 1.0 1.0 0.0", AddRobotForm.request("r", "Scout", "1", "1", "0", ""));
        for (String[] bad : new String[][] {{"two words", "1", "the name must be one word"},
                {"r", "x1", "x must be a number, got \"x1\""}}) {
            IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                    () -> AddRobotForm.request(bad[0], "Scout", bad[1], "1", "0", ""));
            org.junit.jupiter.api.Assertions.assertTrue(e.getMessage().startsWith(bad[2]), e.getMessage());
        }
    }

    @Test
    void aReplyPrintsAsKeyValueLinesWithEachRobotAsNameStateSince() throws Exception {
        String n = System.lineSeparator();
        assertEquals("ok=true" + n + "robots=a:running,b:held:1001" + n, ControlPanelMain.lines(status(
                "{'ok':true,'robots':[{'name':'a','state':'running'},{'name':'b','state':'held','since':1001}]}")));
    }

    @Test
    void aReplayShowsItsRecordingSpeedAndViewers() throws Exception {
        assertEquals("replaying: run.rec\nrecorded:  steps 0 to 4999 (at the end: seek, or stop)\nspeed:     x2.5\n"
                + "viewers:   1", StatusText.details(status("{'replay':true,'file':'run.rec','first_step':0,"
                + "'last_step':4999,'at_end':true,'speed':2.5,'viewers':1}")));
    }

    @Test
    void controlCharactersFromTheNetworkAreNotShown() throws Exception {
        assertEquals("RUN?NING   step 1", StatusText.headline(status("{'state':'RUN\\nNING','step':1}")));
    }
}
