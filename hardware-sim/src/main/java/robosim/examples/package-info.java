/** Example control programs, written only against {@link robosim.api}. */
package robosim.examples;
