package org.robotrun.program;

import java.util.Arrays;
import java.util.Map;

/**
 * How many ports of each I/O kind a controller has (its configured index ranges): {@code DO[i]}
 * is valid for 1 ≤ i ≤ {@code size(DO)}. An index beyond the range alarms when the line runs, as
 * on the controller where the port is not assigned. Defaults are those of an R-30iB with its
 * usual I/O: DI/DO 1..512, robot I/O RI/RO 1..8 (the end-effector connector), GI/GO 1..100,
 * flags F 1..200, operator panel SI/SO 1..15, analog AI/AO 1..64. A scenario may set other sizes per robot ({@code "io"}, docs/scenario-format.md).
 */
public final class IoRanges {
  /** The largest size RobotRun accepts for any kind. */
  public static final int MAX_SIZE = 4096;

  /** DI/DO 512, RI/RO 8, GI/GO 100, F 200. */
  public static final IoRanges DEFAULT = new IoRanges(defaults());

  private final int[] sizes;

  private IoRanges(int[] sizes) {
    this.sizes = sizes;
  }

  private static int[] defaults() {
    int[] s = new int[IoKind.values().length];
    s[IoKind.DI.ordinal()] = 512;
    s[IoKind.DO.ordinal()] = 512;
    s[IoKind.RI.ordinal()] = 8;
    s[IoKind.RO.ordinal()] = 8;
    s[IoKind.GI.ordinal()] = 100;
    s[IoKind.GO.ordinal()] = 100;
    s[IoKind.F.ordinal()] = Registers.FLAG_COUNT;
    // The standard operator panel of an R-30iB: SI[1..15] (FAULT RESET, REMOTE, HOLD, ..., START)
    // and SO[1..15] (CYCLE START, HOLD, FAULT LED, ...); SO[0]/SI[0] are not modelled.
    s[IoKind.SI.ordinal()] = 15;
    s[IoKind.SO.ordinal()] = 15;
    // Analog ports depend on the boards fitted; RobotRun assumes 64 of each unless a scenario says otherwise.
    s[IoKind.AI.ordinal()] = 64;
    s[IoKind.AO.ordinal()] = 64;
    s[IoKind.UI.ordinal()] = 18;
    s[IoKind.UO.ordinal()] = 20;
    return s;
  }

  /**
   * The defaults with the given kinds resized, e.g. {@code {"DO": 1024}}.
   *
   * @throws IllegalArgumentException naming the kind if one is unknown or a size is outside 1..{@link #MAX_SIZE}
   */
  public static IoRanges of(Map<String, Integer> sizes) {
    int[] s = defaults();
    for (Map.Entry<String, Integer> e : sizes.entrySet()) {
      IoKind k = kind(e.getKey());
      int n = e.getValue();
      if (k == IoKind.UI || k == IoKind.UO) {
        throw new IllegalArgumentException(e.getKey() + ": the UOP signals are fixed (UI 1..18, UO 1..20); they cannot be resized");
      }
      if (n < 1 || n > MAX_SIZE) {
        throw new IllegalArgumentException(e.getKey() + ": expected a number of ports 1.." + MAX_SIZE + ", got " + n);
      }
      s[k.ordinal()] = n;
    }
    return new IoRanges(s);
  }

  /** The kind named {@code name} (DI, DO, RI, RO, GI, GO, F, SI, SO, AI, AO). */
  public static IoKind kind(String name) {
    for (IoKind k : IoKind.values()) {
      if (k.name().equals(name)) {
        return k;
      }
    }
    throw new IllegalArgumentException("unknown I/O kind '" + name + "': expected one of "
        + Arrays.toString(IoKind.values()).replace("[", "").replace("]", ""));
  }

  /** The highest valid index of {@code kind}. */
  public int size(IoKind kind) {
    return sizes[kind.ordinal()];
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof IoRanges r && Arrays.equals(sizes, r.sizes);
  }

  @Override
  public int hashCode() {
    return Arrays.hashCode(sizes);
  }

  @Override
  public String toString() {
    StringBuilder b = new StringBuilder("IoRanges[");
    for (IoKind k : IoKind.values()) {
      b.append(k.name()).append('=').append(sizes[k.ordinal()]).append(k.ordinal() == IoKind.values().length - 1 ? "]" : ", ");
    }
    return b.toString();
  }
}
