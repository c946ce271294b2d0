package robosim.rl;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;

/**
 * A learning robot's message as a RoboSim message's text: its numbers (float32) as eight hexadecimal digits each
 * (the bits, so a message arrives exactly as sent), comma-separated. It goes through the world's message routing
 * like any other (to every robot in range) and is read back into the batch's message array.
 */
final class MessageNumbers {
    private static final VarHandle FLOAT = MethodHandles.byteArrayViewVarHandle(float[].class, ByteOrder.LITTLE_ENDIAN);

    private MessageNumbers() {
    }

    /** The text of {@code count} numbers of {@code values} from {@code from}. */
    static String text(float[] values, int from, int count) {
        StringBuilder b = new StringBuilder(count * 9);
        for (int i = 0; i < count; i++) {
            if (i > 0) {
                b.append(',');
            }
            String hex = Integer.toHexString(Float.floatToRawIntBits(values[from + i]));
            b.append("0".repeat(8 - hex.length())).append(hex);
        }
        return b.toString();
    }

    /**
     * Writes the {@code count} numbers of {@code text} into {@code out} (little-endian float32) from byte {@code at};
     * a text that is not {@code count} numbers (none of a learning robot's) is left out.
     */
    static void read(String text, byte[] out, int at, int count) {
        if (text.length() != count * 9 - 1) {
            return;
        }
        for (int i = 0; i < count; i++) {
            int bits;
            try {
                bits = Integer.parseUnsignedInt(text, i * 9, i * 9 + 8, 16);
            } catch (NumberFormatException e) {
                return;
            }
            FLOAT.set(out, at + i * 4, Float.intBitsToFloat(bits));
        }
    }
}
