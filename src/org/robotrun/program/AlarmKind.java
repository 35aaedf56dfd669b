package org.robotrun.program;

/**
 * The interpreter's alarm table. Codes are FANUC-style ({@code INTP-nnn}, the family FANUC uses
 * for program-execution faults); the numbers are RobotRun's own and are not claimed to match a
 * real controller's. A motion port may report its own code (e.g. a frame mismatch); that alarm
 * is {@link #MOTION} with the port's code.
 *
 * <pre>
 * code      kind             raised by
 * INTP-201  TYPE_MISMATCH    arithmetic on ON/OFF, AND/OR on numbers, a real where an integer is needed, Cartesian vs joint PR
 * INTP-202  DIVIDE_BY_ZERO   '/', DIV or MOD by 0
 * INTP-203  BAD_INDEX        register, I/O, PR element, AR or frame index out of range; indirect index not a whole number
 * INTP-204  BAD_VALUE        OVERRIDE outside 1..100, frame number outside 0..10, negative speed
 * INTP-205  UNKNOWN_LABEL    JMP / SELECT / TIMEOUT / Skip to a label the program does not have
 * INTP-206  UNKNOWN_PROGRAM  CALL of a program the store does not have
 * INTP-207  CALL_DEPTH       a CALL that would nest deeper than 32 programs
 * INTP-208  STRUCTURE        FOR without ENDFOR, ELSE/ENDIF without IF…THEN, a SELECT case outside a SELECT…
 * INTP-209  UNDEFINED_POSITION a P[n] the /POS block lacks; plain Offset without an offset condition
 * INTP-210  RUNAWAY          more than the instruction budget in one tick without motion or wait
 * INTP-211  WRITE_PROTECTED  assigning an input (DI, RI, GI)
 * INTP-213  USER_ALARM       UALM[i]
 * INTP-214  ABORTED          ABORT
 * (port's)  MOTION           the motion port refused or failed a motion (frame mismatch, unreachable…)
 * </pre>
 */
public enum AlarmKind {
  TYPE_MISMATCH("INTP-201", "Type mismatch"),
  DIVIDE_BY_ZERO("INTP-202", "Divide by zero"),
  BAD_INDEX("INTP-203", "Invalid index"),
  BAD_VALUE("INTP-204", "Invalid value"),
  UNKNOWN_LABEL("INTP-205", "Label not found"),
  UNKNOWN_PROGRAM("INTP-206", "Program not found"),
  CALL_DEPTH("INTP-207", "Call stack overflow"),
  STRUCTURE("INTP-208", "Statement structure"),
  UNDEFINED_POSITION("INTP-209", "Position not defined"),
  RUNAWAY("INTP-210", "Runaway loop"),
  WRITE_PROTECTED("INTP-211", "Write protected"),
  USER_ALARM("INTP-213", "User alarm"),
  ABORTED("INTP-214", "Program aborted"),
  MOTION("MOTN-000", "Motion failed");

  private final String code;
  private final String title;

  AlarmKind(String code, String title) {
    this.code = code;
    this.title = title;
  }

  /** The default code shown on the pendant, e.g. {@code INTP-202}. */
  public String code() {
    return code;
  }

  /** A short title, e.g. "Divide by zero". */
  public String title() {
    return title;
  }
}
