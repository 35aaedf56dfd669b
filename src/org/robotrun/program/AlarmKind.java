package org.robotrun.program;

/**
 * The interpreter's faults, each with its row in the alarm table ({@link AlarmCode}: code,
 * severity, cause, remedy). A motion port may report its own code (a frame mismatch, a joint
 * limit); that alarm is {@link #MOTION} with the port's code.
 */
public enum AlarmKind {
  TYPE_MISMATCH(AlarmCode.INTP_205),
  DIVIDE_BY_ZERO(AlarmCode.SIMU_001),
  BAD_INDEX(AlarmCode.INTP_204),
  BAD_VALUE(AlarmCode.INTP_304),
  UNKNOWN_LABEL(AlarmCode.INTP_224),
  UNKNOWN_PROGRAM(AlarmCode.INTP_222),
  CALL_DEPTH(AlarmCode.INTP_302),
  STRUCTURE(AlarmCode.SIMU_002),
  UNDEFINED_POSITION(AlarmCode.INTP_311),
  RUNAWAY(AlarmCode.SIMU_003),
  WRITE_PROTECTED(AlarmCode.SIMU_004),
  USER_ALARM(AlarmCode.INTP_213),
  ABORTED(AlarmCode.SIMU_005),
  MOTION(AlarmCode.SIMU_011),
  NOT_SUPPORTED(AlarmCode.SIMU_012),
  RUN_FAILED(AlarmCode.INTP_267),
  /** A TIME/DISTANCE BEFORE/AFTER CALL of a program with a motion group. */
  CALL_GROUP(AlarmCode.INTP_129),
  /** An iRVision fault; the signal carries its CVIS code. */
  VISION(AlarmCode.CVIS_015);

  private final AlarmCode entry;

  AlarmKind(AlarmCode entry) {
    this.entry = entry;
  }

  /** The row of the alarm table. */
  public AlarmCode entry() {
    return entry;
  }

  /** The default code shown on the pendant, e.g. {@code INTP-224}. */
  public String code() {
    return entry.code();
  }

  /** The controller's alarm text, e.g. "Jump label is fail". */
  public String title() {
    return entry.text();
  }
}
