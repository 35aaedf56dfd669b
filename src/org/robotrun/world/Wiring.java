package org.robotrun.world;

import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * Signals wired between robots (issue 15): each wire carries one robot's output to an input of
 * the same or another robot, as the cable between two controllers' I/O boards does. A wired
 * input follows its output with one tick's delay (see {@code sim.WiredIo} and
 * docs/scenario-format.md). The scenario reader checks that both ends exist, that every wire
 * runs from an output to an input of the same width, and that no input has two drivers.
 *
 * @param wires in file order
 */
public record Wiring(List<Wire> wires) {
  /** None: the scenario does not use this. */
  public static final Wiring NONE = new Wiring(List.of());

  public Wiring {
    wires = List.copyOf(wires);
  }

  /** Whether there are no wires. */
  public boolean isEmpty() {
    return wires.isEmpty();
  }

  /**
   * One end of a wire: a port of a robot's controller, written {@code robot1.DO[10]}.
   *
   * @param robot the robot's name in the scenario
   * @param kind the I/O kind as the controller names it ("DO", "DI", "GO" ...), upper case
   * @param index 1-based port number
   */
  public record Signal(String robot, String kind, int index) {
    public Signal {
      Objects.requireNonNull(robot, "robot");
      kind = kind.toUpperCase(Locale.ROOT);
    }

    @Override
    public String toString() {
      return robot + "." + kind + "[" + index + "]";
    }
  }

  /** A wire: {@code from} (an output) drives {@code to} (an input). */
  public record Wire(Signal from, Signal to) {
    public Wire {
      Objects.requireNonNull(from, "from");
      Objects.requireNonNull(to, "to");
    }
  }
}
