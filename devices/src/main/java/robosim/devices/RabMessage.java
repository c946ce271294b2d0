package robosim.devices;

/**
 * One range-and-bearing message a robot received: the sender's distance from it (mm, between the two devices), its
 * bearing as the receiver sees it (degrees from the receiver's heading, counter-clockwise, in (-180, 180]; 0 for a
 * device that senses no bearing) and the bytes it sent (each 0 to 255).
 */
public record RabMessage(double rangeMm, double bearingDeg, int[] data) {
    public RabMessage {
        data = data.clone();
    }

    @Override
    public int[] data() {
        return data.clone();
    }

    /** Its byte {@code k}. */
    public int data(int k) {
        return data[k];
    }

    public int size() {
        return data.length;
    }
}
