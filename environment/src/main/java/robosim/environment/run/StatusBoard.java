package robosim.environment.run;

import java.util.ArrayList;
import java.util.List;

/**
 * Publishes the run's status from its state, on the loop thread, after every event and wherever a log line must
 * find it published: the phase as the control port names it, where geometry is resolved, and, whenever the
 * {@link Roster} or the robots added from the control port have changed since (their versions moved), who has said
 * hello, every robot's state and who has left. Nothing sets a flag to say something changed: what is published
 * is derived from what the parts hold. What it publishes is a {@link PublishedRun}, read by any thread.
 */
final class StatusBoard {
    private final PublishedRun published;
    private final Progress progress;
    private final RunControl control;
    private final GeometryLink geometry;
    private final Roster roster;
    private final Admission admission;
    private long rosterSeen = -1;
    private long addedSeen = -1;

    StatusBoard(PublishedRun published, Progress progress, RunControl control, GeometryLink geometry, Roster roster,
            Admission admission) {
        this.published = published;
        this.progress = progress;
        this.control = control;
        this.geometry = geometry;
        this.roster = roster;
        this.admission = admission;
    }

    /** Publishes the run's phase and where geometry is resolved, and its robots if they changed. */
    void publish() {
        published.phase(switch (progress.phase()) {
            case WAITING -> RunStatus.State.WAITING;
            case ENDED -> RunStatus.State.ENDED;
            default -> control.pausedNow() ? RunStatus.State.PAUSED : RunStatus.State.RUNNING;
        }, geometry.where(progress.over()));
        if (roster.version() != rosterSeen || admission.version() != addedSeen) {
            rosterSeen = roster.version();
            addedSeen = admission.version();
            publishRobots();
        }
    }

    /** The robots that have said hello and whether each takes part, every robot's state, and who has left. */
    private void publishRobots() {
        List<PublishedRun.Member> members = new ArrayList<>();
        for (Roster.Slot s : roster.all()) {
            if (s.peer() != null) {
                members.add(new PublishedRun.Member(s.name(), s.peer(), s.state() != Roster.Slot.State.GONE));
            }
        }
        List<RobotState> states = roster.states();
        List<String> added = admission.added();
        if (!added.isEmpty()) { // (robots the control port added that have not said hello yet, by name)
            states = new ArrayList<>(states);
            for (String name : added) {
                states.add(new RobotState(name, RobotState.ADDED, -1));
            }
        }
        published.robots(members, states, roster.departures());
    }
}
