package robosim.examples;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.file.Files;
import java.util.Arrays;
import robosim.api.Colours;
import robosim.loop.Experiment;
import robosim.loop.LoopFunctions;

/**
 * ARGoS's foraging_loop_functions (examples/argos/foraging.xml): {@code items} food items (discs of {@code radius} m,
 * painted black on the floor) placed at random in the foraging area; before each step, a robot without food that
 * stands on an item outside the nest picks it up (the item leaves the floor; the robot is told {@code food}), and a
 * robot with food in the nest drops it (a new item appears at random; the robot is told {@code dropped};
 * {@code energy_per_item} is earned); every walking robot (its LEDs not red: exploring or returning) spends
 * {@code energy_per_walking_robot} a step. Each step's line goes to {@code output} (ARGoS's columns: clock, walking,
 * resting, collected_food, energy) in the run's output directory, and {@code collected_food} and {@code energy} are
 * reported as the run's metrics. Positions as the world's (ARGoS's shifted by half the 5 m arena): the nest is
 * {@code x < nest_x} (1.5 m), the food area {@code area} ("1.6,0.8,4.2,4.2": min x, min y, max x, max y, m).
 */
public final class ForagingLoopFunctions implements LoopFunctions {
    /** The most items a world may ask for (each a painted disc: the floor holds 10,000 regions). */
    private static final int MAX_ITEMS = 5_000;
    /** Where an item that a robot carries is: nowhere on the floor. */
    private static final double AWAY = Double.NaN;

    private double[] foodX;
    private double[] foodY;
    private double radiusMm;
    private double nestXMm;
    private double[] area;
    private long energyPerItem;
    private long energyPerWalkingRobot;
    private long collected;
    private long energy;
    /** The item each robot carries, or -1. */
    private int[] carried;
    private BufferedWriter output;

    @Override
    public void init(Experiment world) throws IOException {
        int items = (int) world.parameter("items", 15);
        if (items < 0 || items > MAX_ITEMS) {
            throw new IllegalArgumentException("items is 0 to " + MAX_ITEMS + ", got " + items);
        }
        radiusMm = world.parameter("radius", 0.1) * 1000;
        nestXMm = world.parameter("nest_x", 1.5) * 1000;
        area = Arrays.stream(world.parameter("area", "1.6,0.8,4.2,4.2").split(",")).mapToDouble(
                v -> Double.parseDouble(v.trim()) * 1000).toArray();
        if (area.length != 4 || !(area[0] < area[2]) || !(area[1] < area[3])) {
            throw new IllegalArgumentException("area is MINX,MINY,MAXX,MAXY in metres, got "
                    + world.parameter("area", ""));
        }
        energyPerItem = (long) world.parameter("energy_per_item", 1000);
        energyPerWalkingRobot = (long) world.parameter("energy_per_walking_robot", 1);
        collected = 0;
        energy = 0;
        foodX = new double[items];
        foodY = new double[items];
        for (int i = 0; i < items; i++) {
            place(world, i);
        }
        carried = new int[world.robots()];
        Arrays.fill(carried, -1);
        paint(world);
        if (output != null) {
            output.close();
        }
        String file = world.parameter("output", "foraging.txt");
        if (!file.matches("[A-Za-z0-9_.-]{1,64}") || file.startsWith(".")) {
            throw new IllegalArgumentException("output is a file name (letters, digits, _ . -), got " + file);
        }
        output = Files.newBufferedWriter(world.outputDirectory().resolve(file));
        output.write("# clock\twalking\tresting\tcollected_food\tenergy\n");
    }

    private void place(Experiment world, int item) {
        foodX[item] = area[0] + world.random().nextDouble() * (area[2] - area[0]);
        foodY[item] = area[1] + world.random().nextDouble() * (area[3] - area[1]);
    }

    /** The floor as ARGoS's GetFloorColor gives it: each item on the floor a black disc (the nest is the file's). */
    private void paint(Experiment world) {
        world.erasePaint();
        for (int i = 0; i < foodX.length; i++) {
            if (!Double.isNaN(foodX[i])) {
                world.paintDisc(foodX[i], foodY[i], radiusMm, Colours.BLACK);
            }
        }
    }

    @Override
    public void preStep(Experiment world) throws IOException {
        int walking = 0;
        int resting = 0;
        boolean changed = false;
        if (carried.length < world.robots()) { // (robots that joined)
            int before = carried.length;
            carried = Arrays.copyOf(carried, world.robots());
            Arrays.fill(carried, before, carried.length, -1);
        }
        for (int r = 0; r < world.robots(); r++) {
            if (!world.present(r)) {
                if (carried[r] >= 0) { // (it left with an item: the item comes back to the floor)
                    place(world, carried[r]);
                    carried[r] = -1;
                    changed = true;
                }
                continue;
            }
            int[] leds = world.leds(r);
            boolean walks = leds.length > 0 && (leds[0] == Colours.GREEN || leds[0] == Colours.BLUE);
            if (walks) {
                walking++;
            } else {
                resting++;
            }
            double x = world.robotXMm(r);
            double y = world.robotYMm(r);
            if (carried[r] >= 0) {
                if (x < nestXMm) {
                    place(world, carried[r]);
                    carried[r] = -1;
                    energy += energyPerItem;
                    collected++;
                    world.tell(r, "dropped");
                    changed = true;
                }
            } else if (x > nestXMm) {
                for (int i = 0; i < foodX.length; i++) {
                    double dx = x - foodX[i];
                    double dy = y - foodY[i];
                    if (dx * dx + dy * dy < radiusMm * radiusMm) {
                        foodX[i] = AWAY;
                        foodY[i] = AWAY;
                        carried[r] = i;
                        world.tell(r, "food");
                        changed = true;
                        break;
                    }
                }
            }
        }
        if (changed) {
            paint(world);
        }
        energy -= walking * energyPerWalkingRobot;
        output.write(world.step() + "\t" + walking + "\t" + resting + "\t" + collected + "\t" + energy + "\n");
        world.report("collected_food", collected);
        world.report("energy", energy);
    }

    @Override
    public void destroy(Experiment world) throws IOException {
        if (output != null) {
            output.close();
            output = null;
        }
    }
}
