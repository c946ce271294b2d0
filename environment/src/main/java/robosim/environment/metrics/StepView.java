package robosim.environment.metrics;

/**
 * What a metric sees of one step of a run: the world after it. Every robot of the world (those that joined
 * included) has a pose; a robot that took part in the step (it sent a request) also says whether it touches
 * something and how many messages were delivered to it; the tags made and the robots departed are counts so far.
 * Whoever steps a world (its core, or a recording read back) offers one, reused from step to step: a metric reads
 * it during {@link StepMetric#step} and keeps nothing of it.
 */
public interface StepView {
    /** Robots in the world, those that left included. */
    int robots();

    /** Robot {@code robot}'s position at the end of the step, mm. */
    double xMm(int robot);

    double yMm(int robot);

    /** True if robot {@code robot} took part in the step (its request was in); false before the first step. */
    boolean tookPart(int robot);

    /** A robot that took part: it touches something at the end of the step. */
    boolean touching(int robot);

    /** A robot that took part: messages delivered to it with the step. */
    int delivered(int robot);

    /** Tags made so far (distinct tagger and target). */
    int tags();

    /** Robots that have left the world so far. */
    int departed();
}
