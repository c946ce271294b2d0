package robosim.examples;

import java.util.SplittableRandom;
import robosim.api.Colours;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * ARGoS's footbot_foraging (examples/argos/foraging.xml), state by state: resting in the nest (LEDs red), exploring
 * (green: diffusion, with anti-phototaxis while still in the nest), returning to the nest (blue: diffusion plus
 * phototaxis toward the nest's lights), and its probabilistic rules: the food rule, the collision rule and the social
 * rule (what resting robots hear by range-and-bearing of the others' last exploration). Food is the loop functions'
 * ({@link ForagingLoopFunctions}): they tell the robot {@code food} when it stands on an item and {@code dropped}
 * when it brings one into the nest, where ARGoS's loop functions write the controller's food data directly. The
 * parameters are the ARGoS file's, by the same names ({@code <param>}); speeds in mm/s ({@code max_speed} 100, ARGoS's
 * 10 cm/s). Readings: proximity and light, 24 each from 7.5 degrees every 15; ground, ARGoS's order (its readings 2
 * and 3 tell the nest's grey). Its angles and lengths are {@link PortableMath}'s and its chances a
 * {@code SplittableRandom} of the robot's seed, so that its Python twin, {@code examples/python/argos_foraging.py},
 * gives the same pose log.
 */
public final class FootBotForaging implements RobotControl {
    /** What the robot tells the others of its last exploration (range-and-bearing byte 0). */
    private static final int NONE = 0;
    private static final int SUCCESSFUL = 1;
    private static final int UNSUCCESSFUL = 2;
    /** A foot-bot's range-and-bearing record: distance, bearing, then its ten bytes. */
    private static final int RAB_RECORD = 12;

    private enum State { RESTING, EXPLORING, RETURN_TO_NEST }

    private Robot robot;
    private SplittableRandom random;
    // parameters
    private double goStraightMin;
    private double goStraightMax;
    private double delta;
    private WheelTurning wheels;
    private double maxSpeed;
    private double foodExploreToRest;
    private double foodRestToExplore;
    private double collisionExploreToRest;
    private double socialExploreToRest;
    private double socialRestToExplore;
    private int minimumRestingTime;
    private int minimumUnsuccessfulExploreTime;
    private int minimumSearchForPlaceInNestTime;
    // state
    private State state = State.RESTING;
    private boolean inNest = true;
    private double restToExplore;
    private double exploreToRest;
    private int timeExploringUnsuccessfully;
    private int timeRested;
    private int timeSearchingForPlaceInNest;
    private int lastExploration = NONE;
    private boolean hasFood;
    private int totalFood;

    @Override
    public void run(Robot r) throws InterruptedException {
        robot = r;
        random = new SplittableRandom(r.seed());
        String[] range = r.parameter("go_straight_angle_range", "-5:5").split(":");
        if (range.length != 2) {
            throw new IllegalArgumentException("go_straight_angle_range is MIN:MAX in degrees, got "
                    + String.join(":", range));
        }
        goStraightMin = PortableMath.RADIANS_PER_DEGREE * Double.parseDouble(range[0].trim());
        goStraightMax = PortableMath.RADIANS_PER_DEGREE * Double.parseDouble(range[1].trim());
        delta = r.parameter("delta", 0.1);
        wheels = new WheelTurning(r, 100.0, 1);
        maxSpeed = wheels.maxSpeed();
        restToExplore = r.parameter("initial_rest_to_explore_prob", 0.1);
        exploreToRest = r.parameter("initial_explore_to_rest_prob", 0.1);
        foodExploreToRest = r.parameter("food_rule_explore_to_rest_delta_prob", 0.01);
        foodRestToExplore = r.parameter("food_rule_rest_to_explore_delta_prob", 0.01);
        collisionExploreToRest = r.parameter("collision_rule_explore_to_rest_delta_prob", 0.01);
        socialExploreToRest = r.parameter("social_rule_explore_to_rest_delta_prob", 0.01);
        socialRestToExplore = r.parameter("social_rule_rest_to_explore_delta_prob", 0.01);
        minimumRestingTime = (int) r.parameter("minimum_resting_time", 50.0);
        minimumUnsuccessfulExploreTime = (int) r.parameter("minimum_unsuccessful_explore_time", 600.0);
        minimumSearchForPlaceInNestTime = (int) r.parameter("minimum_search_for_place_in_nest_time", 50.0);
        timeRested = minimumRestingTime; // (ARGoS's: a decision at the start, not after a wait)
        r.setLeds(Colours.RED);
        say(NONE);
        r.step(); // (readings come with a step: none before the first)
        while (true) {
            hear();
            switch (state) {
                case RESTING -> rest();
                case EXPLORING -> explore();
                case RETURN_TO_NEST -> returnToNest();
                default -> throw new IllegalStateException(state.name());
            }
            robot.report("food_items", totalFood);
            robot.step();
        }
    }

    /** The loop functions' word on the robot's food: {@code food} (it picked an item up), {@code dropped} (in the nest). */
    private void hear() {
        for (Message m = robot.receive(); m != null; m = robot.receive()) {
            if (!"loop".equals(m.from())) {
                continue;
            }
            if ("food".equals(m.text())) {
                hasFood = true;
            } else if ("dropped".equals(m.text())) {
                hasFood = false;
                totalFood++;
            }
        }
    }

    private void rest() {
        if (timeRested > minimumRestingTime && random.nextDouble() < restToExplore) {
            robot.setLeds(Colours.GREEN);
            state = State.EXPLORING;
            timeRested = 0;
            return;
        }
        timeRested++;
        if (timeRested == 1) {
            say(NONE); // (the last exploration's result is told once)
        }
        double[] heard = robot.sensor("rab");
        for (int k = 0; k + RAB_RECORD <= heard.length; k += RAB_RECORD) {
            int said = (int) heard[k + 2];
            if (said == SUCCESSFUL) {
                restToExplore = clamp(restToExplore + socialRestToExplore);
                exploreToRest = clamp(exploreToRest - socialExploreToRest);
            } else if (said == UNSUCCESSFUL) {
                exploreToRest = clamp(exploreToRest + socialExploreToRest);
                restToExplore = clamp(restToExplore - socialRestToExplore);
            }
        }
    }

    private void explore() {
        boolean returnToNest = false;
        if (hasFood) {
            exploreToRest = clamp(exploreToRest - foodExploreToRest);
            restToExplore = clamp(restToExplore + foodRestToExplore);
            lastExploration = SUCCESSFUL;
            returnToNest = true;
        } else if (timeExploringUnsuccessfully > minimumUnsuccessfulExploreTime) {
            if (random.nextDouble() < exploreToRest) {
                lastExploration = UNSUCCESSFUL;
                returnToNest = true;
            } else {
                exploreToRest = clamp(exploreToRest + foodExploreToRest);
                restToExplore = clamp(restToExplore - foodRestToExplore);
            }
        }
        if (returnToNest) {
            timeExploringUnsuccessfully = 0;
            timeSearchingForPlaceInNest = 0;
            robot.setLeds(Colours.BLUE);
            state = State.RETURN_TO_NEST;
            return;
        }
        timeExploringUnsuccessfully++;
        updateInNest();
        double[] diffusion = new double[2];
        boolean collision = diffusion(diffusion);
        if (collision) {
            exploreToRest = clamp(exploreToRest + collisionExploreToRest);
            restToExplore = clamp(restToExplore - collisionExploreToRest);
        }
        if (inNest) {
            double[] light = toLight();
            wheels.drive(robot, maxSpeed * diffusion[0] - maxSpeed * 0.25 * light[0],
                    maxSpeed * diffusion[1] - maxSpeed * 0.25 * light[1]);
        } else {
            wheels.drive(robot, maxSpeed * diffusion[0], maxSpeed * diffusion[1]);
        }
    }

    private void returnToNest() {
        updateInNest();
        if (inNest) {
            if (timeSearchingForPlaceInNest > minimumSearchForPlaceInNestTime) {
                robot.setWheelSpeeds(0, 0);
                say(lastExploration);
                robot.setLeds(Colours.RED);
                state = State.RESTING;
                timeSearchingForPlaceInNest = 0;
                lastExploration = NONE;
                return;
            }
            timeSearchingForPlaceInNest++;
        } else {
            timeSearchingForPlaceInNest = 0;
        }
        double[] diffusion = new double[2];
        diffusion(diffusion);
        double[] light = toLight();
        wheels.drive(robot, maxSpeed * diffusion[0] + maxSpeed * light[0], maxSpeed * diffusion[1] + maxSpeed * light[1]);
    }

    /** Sets the range-and-bearing message: byte 0 the last exploration's result, the other nine 0. */
    private void say(int result) {
        int[] bytes = new int[RAB_RECORD - 2];
        bytes[0] = result;
        robot.setRabData(bytes);
    }

    /** In the nest when both of ARGoS's readings 2 and 3 of the ground read its grey. */
    private void updateInNest() {
        double[] ground = robot.sensor("ground");
        inNest = ground[2] > 0.25 && ground[2] < 0.75 && ground[3] > 0.25 && ground[3] < 0.75;
    }

    /**
     * ARGoS's diffusion vector, into {@code out} (x ahead, y left): straight ahead (1, 0) when the proximity readings'
     * sum points within the go-straight range and is shorter than {@code delta}, else away from it, of length 1;
     * true in the second case (a collision avoided).
     */
    private boolean diffusion(double[] out) {
        double[] sum = FootBotRing.sum(robot.sensor("proximity"));
        double x = sum[0];
        double y = sum[1];
        double angle = PortableMath.angle(y, x);
        double length = PortableMath.length(x, y);
        if (angle >= goStraightMin && angle <= goStraightMax && length < delta) {
            out[0] = 1;
            out[1] = 0;
            return false;
        }
        out[0] = length > 0 ? -x / length : 0;
        out[1] = length > 0 ? -y / length : 0;
        return true;
    }

    /** A unit vector toward the light the light sensors sense most, or (0, 0) if they sense none. */
    private double[] toLight() {
        double[] sum = FootBotRing.sum(robot.sensor("light"));
        double x = sum[0];
        double y = sum[1];
        double length = PortableMath.length(x, y);
        return length > 0 ? new double[] {x / length, y / length} : new double[] {0, 0};
    }

    private static double clamp(double p) {
        return Math.max(0, Math.min(1, p));
    }
}
