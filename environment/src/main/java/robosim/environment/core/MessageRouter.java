package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import robosim.protocol.CommEvent;

/**
 * Routes COMMEVENT messages between robots: a message sent in step k is delivered in the
 * recipient's response to step k, after every message sent to it before, in the order the
 * senders are listed in the world and each sender's own order. {@code to} is a robot's name, or
 * {@link CommEvent#EVERYONE} for every other robot. A message to an unknown or departed robot, or larger than
 * the world's limit, is not delivered and the sender is told why. With a communication range, a
 * message to a robot farther away (centre to centre, at the start of the step) is dropped and
 * counted, like a radio message that does not arrive; the sender is not told. A robot that is away
 * (held for its return) keeps what is sent to it, up to {@link #AWAY_INBOX} messages (past that the sender
 * is told), and gets it all, in order, in its first response after it is back.
 */
final class MessageRouter {
    /** Messages kept for a robot that is away; one more is refused with a notice to its sender. */
    static final int AWAY_INBOX = 1_000;

    private final Map<String, Integer> index;
    private final double rangeMm;
    private final int maxBytes;
    private final List<List<CommEvent>> inbox;
    private final List<List<String>> notices;
    private boolean[] away;
    private long delivered;
    private long undeliverable;
    private long outOfRange;
    private long tooLarge;

    MessageRouter(Map<String, Integer> index, int robots, double rangeMm, int maxBytes) {
        this.index = index;
        this.rangeMm = rangeMm;
        this.maxBytes = maxBytes;
        this.inbox = new ArrayList<>(robots);
        this.notices = new ArrayList<>(robots);
        this.away = new boolean[robots];
        for (int i = 0; i < robots; i++) {
            inbox.add(new ArrayList<>());
            notices.add(new ArrayList<>());
        }
    }

    /** Robot {@code robot}, the last, has joined under {@code name}. */
    void add(int robot, String name) {
        index.put(name, robot);
        inbox.add(new ArrayList<>());
        notices.add(new ArrayList<>());
        away = java.util.Arrays.copyOf(away, robot + 1);
    }

    /** Routes robot {@code from}'s messages of this step; positions are read from {@code map}. */
    void route(int from, String fromName, List<CommEvent> messages, EnvironmentMap map) {
        for (CommEvent m : messages) {
            int bytes = robosim.protocol.Limits.utfLength(m.payload());
            if (bytes > maxBytes) {
                notice(from, "message to " + m.to() + " not sent: " + bytes + " bytes is more than the limit of "
                        + maxBytes);
                tooLarge++;
                continue;
            }
            if (CommEvent.EVERYONE.equals(m.to())) {
                for (int to = 0; to < inbox.size(); to++) {
                    if (to != from && !map.isGone(to)) {
                        deliver(from, fromName, to, map.name(to), m.payload(), map);
                    }
                }
                continue;
            }
            Integer to = index.get(m.to());
            if (to == null) {
                notice(from, "message to " + m.to() + " not delivered: no robot of that name");
                undeliverable++;
            } else if (map.isGone(to)) {
                notice(from, "message to " + m.to() + " not delivered: that robot has left");
                undeliverable++;
            } else {
                deliver(from, fromName, to, m.to(), m.payload(), map);
            }
        }
    }

    private void deliver(int from, String fromName, int to, String toName, String payload, EnvironmentMap map) {
        if (rangeMm > 0 && Math.hypot(map.xMm(from) - map.xMm(to), map.yMm(from) - map.yMm(to)) > rangeMm) {
            outOfRange++;
            return;
        }
        if (away[to] && inbox.get(to).size() >= AWAY_INBOX) {
            notice(from, "message to " + toName + " not delivered: it is away and " + AWAY_INBOX
                    + " messages already wait for its return");
            undeliverable++;
            return;
        }
        inbox.get(to).add(new CommEvent(fromName, toName, payload));
        delivered++;
    }

    /**
     * A message from the world's loop functions ({@code from}) to robot {@code to}, in its inbox as another robot's
     * (none to a robot that has left); a text over the world's limit is an IllegalArgumentException.
     */
    void fromLoop(int to, EnvironmentMap map, String from, String text) {
        int bytes = robosim.protocol.Limits.utfLength(text);
        if (bytes > maxBytes) {
            throw new IllegalArgumentException("a message of " + bytes + " bytes is more than the world's limit of "
                    + maxBytes);
        }
        if (map.isGone(to)) {
            return;
        }
        int most = away[to] ? AWAY_INBOX : robosim.protocol.Limits.MAX_MESSAGES_PER_STEP;
        if (inbox.get(to).size() >= most) {
            throw new IllegalStateException(most + " messages wait for " + map.name(to) + " already"
                    + (away[to] ? " (it is away)" : ""));
        }
        inbox.get(to).add(new CommEvent(from, map.name(to), text)); // (not counted as a robot's message delivered)
    }

    void notice(int robot, String text) {
        notices.get(robot).add(text);
    }

    /** Robot {@code robot} is away (its messages wait in its inbox) or back. */
    void away(int robot, boolean isAway) {
        away[robot] = isAway;
    }

    /** Messages taken for {@code robot} that never reached it: they go back before what waits for it now. */
    void putBack(int robot, List<CommEvent> messages) {
        if (messages.isEmpty()) {
            return;
        }
        List<CommEvent> l = new ArrayList<>(messages);
        l.addAll(inbox.get(robot));
        inbox.set(robot, l);
    }

    /** This step's messages for {@code robot}, removed from its inbox; none while it is away. */
    List<CommEvent> takeInbox(int robot) {
        return away[robot] ? List.of() : take(inbox, robot);
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

    long outOfRange() {
        return outOfRange;
    }

    long tooLarge() {
        return tooLarge;
    }
}
