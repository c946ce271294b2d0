/**
 * The robot API that control code is written against. Nothing here names the simulator: the same
 * control code runs on a real robot that implements {@link robosim.api.Robot}. Units: millimetres,
 * degrees (counter-clockwise), milliseconds. Called only from the control code's own thread.
 * Module {@code robot-api}: no dependencies; what it promises to keep stable is in its README.
 */
package robosim.api;
