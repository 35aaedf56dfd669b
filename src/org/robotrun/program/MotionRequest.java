package org.robotrun.program;

import java.util.Objects;
import java.util.Optional;

/**
 * One motion statement with everything resolved that the program decides: positions looked up,
 * register speeds and CNT read, offsets fetched. The motion port turns it into a trajectory.
 *
 * @param type J, L, C or A
 * @param target the end point
 * @param via for C motion the via point (the first line's target); empty otherwise
 * @param speed the speed number, in {@code speedUnit} (before override: the port applies it)
 * @param speedUnit the unit as written
 * @param fine true for FINE; otherwise {@code cnt} (0..100) says how early to blend
 * @param cnt CNT value (0 for FINE)
 * @param offset {@code Offset,PR[i]}: shift of the target in the target's user frame
 * @param toolOffset {@code Tool_Offset,PR[i]}: shift of the target in its tool frame
 * @param accPercent {@code ACCn}, 100 when absent
 * @param wristJoint {@code Wjnt}
 * @param incremental {@code INC}: the target is relative to the current position
 * @param backward true when run by backward execution (BWD)
 * @param program the program of the motion line (for the port's alarms)
 * @param line its line number
 * @param viaOwnOffsets true when the C motion's via point carries options of its own ({@code C P[1]
 *     Offset,PR[2]}): then {@code viaOffset}/{@code viaToolOffset} shift the via point and
 *     {@code offset}/{@code toolOffset} the end point only; false: both points take the latter
 * @param viaOffset the via point's own {@code Offset}
 * @param viaToolOffset the via point's own {@code Tool_Offset}
 */
public record MotionRequest(Motion.Type type, Waypoint target, Optional<Waypoint> via, double speed,
    Motion.SpeedUnit speedUnit, boolean fine, int cnt, Optional<Position> offset, Optional<Position> toolOffset,
    int accPercent, boolean wristJoint, boolean incremental, boolean backward, String program, int line,
    boolean viaOwnOffsets, Optional<Position> viaOffset, Optional<Position> viaToolOffset) {

  public MotionRequest {
    Objects.requireNonNull(type, "type");
    Objects.requireNonNull(target, "target");
    Objects.requireNonNull(via, "via");
    Objects.requireNonNull(speedUnit, "speedUnit");
    Objects.requireNonNull(offset, "offset");
    Objects.requireNonNull(toolOffset, "toolOffset");
    Objects.requireNonNull(program, "program");
    Objects.requireNonNull(viaOffset, "viaOffset");
    Objects.requireNonNull(viaToolOffset, "viaToolOffset");
  }

  /** A request whose via point (if any) takes the same offsets as its target. */
  public MotionRequest(Motion.Type type, Waypoint target, Optional<Waypoint> via, double speed,
      Motion.SpeedUnit speedUnit, boolean fine, int cnt, Optional<Position> offset, Optional<Position> toolOffset,
      int accPercent, boolean wristJoint, boolean incremental, boolean backward, String program, int line) {
    this(type, target, via, speed, speedUnit, fine, cnt, offset, toolOffset, accPercent, wristJoint, incremental,
        backward, program, line, false, Optional.empty(), Optional.empty());
  }

  /**
   * A position to reach with the frames it is expressed in. A local P[] carries the UF/UT it
   * was taught in; a PR carries the frames active when the motion was issued. The port reports a
   * mismatch between {@code userFrame}/{@code toolFrame} and the active frames as an alarm.
   *
   * @param name how the program names it, for messages: {@code P[2:PICK]}, {@code PR[5]}
   */
  public record Waypoint(String name, Position position, int userFrame, int toolFrame) {
    public Waypoint {
      Objects.requireNonNull(name, "name");
      Objects.requireNonNull(position, "position");
    }
  }
}
