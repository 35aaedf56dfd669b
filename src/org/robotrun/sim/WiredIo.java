package org.robotrun.sim;

import java.util.List;
import org.robotrun.program.IoKind;
import org.robotrun.program.IoRanges;
import org.robotrun.program.Registers;
import org.robotrun.world.Wiring;

/**
 * The cell's wires, resolved to the controllers' I/O tables. {@link #propagate} copies every
 * wired output to its input; the simulation calls it once at the end of each tick, after every
 * controller has run, so an output a program sets during tick n is seen by the wired input's
 * reader from tick n + 1 (4 ms later), whichever robot runs first. Nothing depends on the order
 * of the controllers, and the run is deterministic.
 *
 * <p>A wired input follows its output every tick: forcing it by hand from the pendant lasts
 * until the end of the tick.
 */
final class WiredIo {
  private final Registers[] from;
  private final IoKind[] fromKind;
  private final int[] fromIndex;
  private final Registers[] to;
  private final IoKind[] toKind;
  private final int[] toIndex;

  private WiredIo(int n) {
    from = new Registers[n];
    fromKind = new IoKind[n];
    fromIndex = new int[n];
    to = new Registers[n];
    toKind = new IoKind[n];
    toIndex = new int[n];
  }

  /** No wires. */
  static final WiredIo NONE = new WiredIo(0);

  /**
   * @throws IllegalArgumentException if a wire names a robot that is not among {@code controllers}
   *     or a port it does not have (the scenario reader reports these with a line first)
   */
  static WiredIo of(Wiring wiring, List<Controller> controllers) {
    WiredIo w = new WiredIo(wiring.wires().size());
    for (int i = 0; i < wiring.wires().size(); i++) {
      Wiring.Wire x = wiring.wires().get(i);
      w.from[i] = registers(x.from(), controllers);
      w.fromKind[i] = IoRanges.kind(x.from().kind());
      w.fromIndex[i] = x.from().index();
      w.to[i] = registers(x.to(), controllers);
      w.toKind[i] = IoRanges.kind(x.to().kind());
      w.toIndex[i] = x.to().index();
      // Reading both ends once checks the indices against the controllers' sizes.
      w.from[i].value(w.fromKind[i], w.fromIndex[i]);
      w.to[i].value(w.toKind[i], w.toIndex[i]);
    }
    return w;
  }

  private static Registers registers(Wiring.Signal s, List<Controller> controllers) {
    for (Controller c : controllers) {
      if (c.name().equals(s.robot())) {
        return c.registers();
      }
    }
    throw new IllegalArgumentException("wiring: no robot named " + s.robot());
  }

  /** Copies every wired output to its input. */
  void propagate() {
    for (int i = 0; i < from.length; i++) {
      to[i].setValue(toKind[i], toIndex[i], from[i].value(fromKind[i], fromIndex[i]));
    }
  }

  int size() {
    return from.length;
  }
}
