package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import robosim.protocol.CommEvent;

/**
 * Routes COMMEVENT messages between robots: a message sent in step k is delivered in the
 * recipient's response to step k, after every message sent to it before, in the order the
 * senders are listed in the world and each sender's own order. A message to an unknown or departed
 * robot is not delivered and the sender is told why.
 */
final class MessageRouter {
    private final Map<String, Integer> index;
    private final List<List<CommEvent>> inbox;
    private final List<List<String>> notices;
    private final boolean[] present;
    private long delivered;
    private long undeliverable;

    MessageRouter(Map<String, Integer> index, int robots) {
        this.index = index;
        this.inbox = new ArrayList<>(robots);
        this.notices = new ArrayList<>(robots);
        for (int i = 0; i < robots; i++) {
            inbox.add(new ArrayList<>());
            notices.add(new ArrayList<>());
        }
        this.present = new boolean[robots];
        java.util.Arrays.fill(present, true);
    }

    void depart(int robot) {
        present[robot] = false;
    }

    void route(int from, String fromName, List<CommEvent> messages) {
        for (CommEvent m : messages) {
            Integer to = index.get(m.to());
            if (to == null) {
                notice(from, "message to " + m.to() + " not delivered: no robot of that name");
                undeliverable++;
            } else if (!present[to]) {
                notice(from, "message to " + m.to() + " not delivered: that robot has left");
                undeliverable++;
            } else {
                inbox.get(to).add(new CommEvent(fromName, m.to(), m.payload()));
                delivered++;
            }
        }
    }

    void notice(int robot, String text) {
        notices.get(robot).add(text);
    }

    /** This step's messages for {@code robot}, removed from its inbox. */
    List<CommEvent> takeInbox(int robot) {
        return take(inbox, robot);
    }

    List<String> takeNotices(int robot) {
        return take(notices, robot);
    }

    private static <T> List<T> take(List<List<T>> lists, int robot) {
        List<T> l = lists.get(robot);
        if (l.isEmpty()) {
            return List.of();
        }
        lists.set(robot, new ArrayList<>());
        return l;
    }

    long delivered() {
        return delivered;
    }

    long undeliverable() {
        return undeliverable;
    }
}
