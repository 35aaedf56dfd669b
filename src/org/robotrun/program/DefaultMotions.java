package org.robotrun.program;

import java.util.List;

/**
 * The pendant's standard default-motion table (the POINT key's list on FANUC's teach pendant):
 * {@code J P[] 100% FINE}, {@code J P[] 100% CNT100}, {@code L P[] 100mm/sec FINE}, {@code L P[]
 * 100mm/sec CNT100}. The pendant records new motions from it, and the .LS reader completes a
 * hand-edited motion that lacks its speed or termination from its first entry of that type.
 */
public final class DefaultMotions {
  private DefaultMotions() {}

  /** One row: a motion type with its speed and termination. */
  public record Row(Motion.Type type, Motion.Speed speed, Motion.Termination termination) {}

  /** FANUC's four standard defaults, in the pendant's order. */
  public static final List<Row> STANDARD = List.of(
      new Row(Motion.Type.J, new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT), new Motion.Fine()),
      new Row(Motion.Type.J, new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT), new Motion.Cnt(100)),
      new Row(Motion.Type.L, new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.MM_PER_SEC), new Motion.Fine()),
      new Row(Motion.Type.L, new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.MM_PER_SEC), new Motion.Cnt(100)));

  /**
   * The first row of {@code type}; the table has no C or A row (the pendant makes a circular
   * motion from a linear one), so C and A take the first L row.
   */
  public static Row first(Motion.Type type) {
    Motion.Type look = type == Motion.Type.J ? Motion.Type.J : Motion.Type.L;
    for (Row r : STANDARD) {
      if (r.type() == look) {
        return r;
      }
    }
    throw new IllegalStateException("no default motion of type " + look);
  }
}
