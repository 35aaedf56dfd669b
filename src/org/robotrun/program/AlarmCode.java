package org.robotrun.program;

import java.util.Arrays;
import java.util.Optional;

/**
 * The alarm table: every alarm RobotRun raises, with the controller's code and text, its
 * severity, and a cause and remedy written for students. docs/alarms.md is this table in prose;
 * a test checks that every alarm code the sources can raise has a row here.
 *
 * <p>Codes of the controller's families (INTP, MOTN, SRVO) are the FANUC R-30iB codes for the
 * same fault; {@link Source} says how each one was checked. Where no controller code fits (a
 * simulator-only fault, or one whose controller code could not be verified), the alarm is in
 * RobotRun's own family {@code SIMU-nnn}, so it can never be mistaken for a controller's.
 */
public enum AlarmCode {
  // ---- servo and safety ---------------------------------------------------------------------
  SRVO_001("SRVO-001", AlarmSeverity.SERVO, "Operator panel E-stop", Source.VERIFIED,
      "The emergency stop button on the operator panel was pressed. The arm stopped at once and the servo power is off.",
      "Make the cell safe, then twist the operator panel E-stop out (RELEASE ESTOP) and press RESET."),
  SRVO_002("SRVO-002", AlarmSeverity.SERVO, "Teach pendant E-stop", Source.VERIFIED,
      "The emergency stop button on the teach pendant was pressed. The arm stopped at once and the servo power is off.",
      "Make the cell safe, then twist the pendant E-stop out (RELEASE ESTOP) and press RESET."),
  SRVO_003("SRVO-003", AlarmSeverity.SERVO, "Deadman switch released", Source.VERIFIED,
      "The teach pendant is enabled (TP ON) but the DEADMAN switch was let go (or squeezed too hard). The arm stopped at once.",
      "Hold the DEADMAN in its middle position and press RESET. To run from the operator panel instead, "
          + "turn the pendant off (TP OFF) and the mode switch to AUTO."),
  SRVO_050("SRVO-050", AlarmSeverity.SERVO, "Collision Detect alarm", Source.VERIFIED,
      "The arm (or its tool or a held part) touched something in the cell. The arm stopped at once; the program paused.",
      "RESET, then jog the arm clear with SHIFT held (slowly: lower the override), and fix the position or path that "
          + "led into the obstacle before running again."),

  // ---- program (interpreter) ----------------------------------------------------------------
  INTP_205("INTP-205", AlarmSeverity.ABORT, "Variable type mismatch", Source.RECALLED,
      "A value of the wrong type was used: arithmetic on ON/OFF, AND/OR on numbers, a real number where a whole number "
          + "is needed, or a joint PR where a Cartesian one is needed.",
      "Look at the line the alarm names and check the type of every register and I/O it uses."),
  INTP_204("INTP-204", AlarmSeverity.ABORT, "Invalid value for index", Source.RECALLED,
      "A register, I/O, PR element, argument or frame index is out of range, or an indirect index (R[R[1]]) is not "
          + "a whole number.",
      "Check the index the message shows (and the register that holds it, for an indirect index)."),
  INTP_213("INTP-213", AlarmSeverity.ABORT, "UALM", Source.RECALLED,
      "The program raised its own user alarm (UALM[i]) with the text set on the user alarm screen.",
      "Read the text: the program's author says there what went wrong. Fix it, RESET, and continue."),
  INTP_222("INTP-222", AlarmSeverity.ABORT, "Call program failed", Source.RECALLED,
      "CALL (or SHIFT+FWD) names a program that does not exist.",
      "Check the program name on the SELECT screen; create or load the program, or fix the CALL."),
  INTP_224("INTP-224", AlarmSeverity.ABORT, "Jump label is fail", Source.VERIFIED,
      "JMP LBL[n] (or SELECT, a WAIT TIMEOUT, a Skip condition) jumps to a label the program does not have.",
      "Add the LBL[n] the jump needs, or correct the label number in the jump."),
  INTP_302("INTP-302", AlarmSeverity.ABORT, "Stack overflow", Source.RECALLED,
      "Programs call each other deeper than the controller allows (usually a program that CALLs itself without end).",
      "Follow the CALLs from the program the alarm names and break the loop."),
  INTP_304("INTP-304", AlarmSeverity.ABORT, "Specified value exceeds limit", Source.VERIFIED,
      "A value is outside what the instruction accepts: OVERRIDE outside 1..100, a frame number outside 0..10, CNT "
          + "outside 0..100, ACC outside 0..150, a speed not above 0; or arithmetic overflowed what a register holds.",
      "Change the value on the line to one inside the range the message shows."),
  INTP_105("INTP-105", AlarmSeverity.WARN, "Run request failed", Source.VERIFIED,
      "A program could not be started from the PLC (a UOP start, RSR or PNS) or by BG Logic: it is already running, "
          + "does not exist, or needs motion group 1 while another task holds it (cause PROG-040). A warning: the "
          + "programs already running go on.",
      "Read the cause in the message. Wait until the other task ends (or ABORT it), give a program that only sets "
          + "I/O and registers no motion group (DEFAULT_GROUP = *,*,*,*,*), or create the program the PLC selects."),
  INTP_267("INTP-267", AlarmSeverity.WARN, "RUN stmt failed", Source.RECALLED,
      "A RUN statement could not start its program as a task. The cause follows the code: PROG-007 (the program is "
          + "already running), PROG-040 (motion group 1 is held by another task), or the program does not exist "
          + "(MEMO-073). A warning: the program that ran RUN goes on with its next line, and so does every other.",
      "Read the cause. Let the running copy end (or ABORT it), give the program you RUN no motion group "
          + "(DEFAULT_GROUP = *,*,*,*,*) when another task moves the arm, or load the program the RUN names."),
  PROG_007("PROG-007", AlarmSeverity.WARN, "Program is already running", Source.RECALLED,
      "The cause under INTP-267: RUN named a program that is running as a task already; one program runs once.",
      "Wait until the task ends (or ABORT it) before running it again, or RUN another program."),
  MEMO_073("MEMO-073", AlarmSeverity.WARN, "Program does not exist", Source.VERIFIED,
      "The cause under INTP-267 (or INTP-105 for a start from the PLC): the program to start is not on the controller.",
      "Load or create the program, or correct the name the RUN (or the PLC's PNS/STYLE number) gives."),
  INTP_129("INTP-129", AlarmSeverity.ABORT, "Cannot use motion group for call", Source.RECALLED,
      "A TIME BEFORE, TIME AFTER or DISTANCE BEFORE option CALLs a program that has a motion group: a program "
          + "called this way runs beside the motion and may not hold the arm.",
      "Give the called program no motion group (DEFAULT_GROUP = *,*,*,*,* on its DETAIL screen), or move "
          + "its motion lines back into the main program."),
  PROG_040("PROG-040", AlarmSeverity.WARN, "Already locked by other task", Source.VERIFIED,
      "The cause under INTP-267 (RUN) and INTP-105 (a start from the PLC): motion group 1 is reserved by another "
          + "running program, so a second program that "
          + "moves the arm cannot start. Two tasks never move the same arm at once.",
      "Check the running tasks (SELECT marks them; the PLC panel lists them): end the one that holds the group first, or remove "
          + "the motion group from the program you RUN."),
  SIMU_021("SIMU-021", AlarmSeverity.ABORT, "Motion in a task without a group", Source.OWN,
      "A program whose motion group mask is empty (DEFAULT_GROUP = *,*,*,*,*) reached a motion statement. A "
          + "controller does not let such a program hold motion lines at all.",
      "Give the program motion group 1 (and run it when no other task moves the arm), or move the motion lines to "
          + "the program that owns the arm."),
  SRVO_037("SRVO-037", AlarmSeverity.SERVO, "IMSTP input (Group:1)", Source.RECALLED,
      "The PLC turned the UOP input *IMSTP (UI[1], normally ON) off: an immediate stop, as an E-stop from the "
          + "cell. The arm stopped at once and the program paused.",
      "Turn UI[1] *IMSTP back on (on the PLC panel or in the PLC program), then FAULT RESET (UI[5]) or RESET."),
  INTP_311("INTP-311", AlarmSeverity.ABORT, "Uninitialized data is used", Source.VERIFIED,
      "The line uses a position P[n] that was never taught (the program's /POS block has no P[n]), or an Offset "
          + "with no OFFSET CONDITION set.",
      "Teach the position (move the arm there and TOUCHUP), or add the OFFSET CONDITION before the move."),

  // ---- motion -------------------------------------------------------------------------------
  MOTN_017("MOTN-017", AlarmSeverity.STOP, "Limit error", Source.VERIFIED,
      "A joint would have to pass its limit to reach the target or a point on the way to it.",
      "RESET, then choose a target the joints can reach, another configuration (CONFIG), or a joint move (J) "
          + "instead of a straight line (L)."),
  MOTN_018("MOTN-018", AlarmSeverity.STOP, "Position not reachable", Source.RECALLED,
      "The target (or a point of the straight or circular path) is out of the arm's reach.",
      "RESET and move the target closer to the robot, or check the user and tool frames it was taught in."),
  MOTN_023("MOTN-023", AlarmSeverity.STOP, "In singularity", Source.VERIFIED,
      "A straight or circular move runs the wrist into its singularity (J5 near 0: J4 and J6 in line), where the "
          + "joints would have to turn infinitely fast.",
      "RESET, then tilt the tool a little at that point so J5 stays away from 0, or use a joint move (J) there."),

  // ---- vision (iRVision) ----------------------------------------------------------------------
  // The CVIS family is the controller's; these numbers could not be checked against its alarm manual
  // (Source.ASSUMED, docs/alarms.md and docs/vision.md say so).
  CVIS_015("CVIS-015", AlarmSeverity.ABORT, "Vision process not found", Source.ASSUMED,
      "VISION RUN_FIND, GET_OFFSET or GET_NFOUND names a vision process the cell does not have.",
      "Check the name between the quotes against the scenario's vision.processes (names are not case-sensitive)."),
  CVIS_016("CVIS-016", AlarmSeverity.ABORT, "Invalid vision register index", Source.ASSUMED,
      "A vision register index is outside VR[1..10].",
      "Use a vision register 1..10 (and check the R[] that holds an indirect index)."),
  CVIS_017("CVIS-017", AlarmSeverity.ABORT, "Vision register is empty", Source.ASSUMED,
      "PR[i]=VR[j].OFFSET, R[i]=VR[j].MODELID or VOFFSET,VR[j] reads a vision register no GET_OFFSET has filled.",
      "Run VISION RUN_FIND, then VISION GET_OFFSET into that VR (with its JMP for nothing found) before using it."),
  CVIS_018("CVIS-018", AlarmSeverity.ABORT, "Vision process has not run", Source.ASSUMED,
      "VISION GET_OFFSET or GET_NFOUND asks a vision process for results before any VISION RUN_FIND of it.",
      "Put VISION RUN_FIND 'NAME' before the GET_OFFSET / GET_NFOUND of the same process."),
  CVIS_019("CVIS-019", AlarmSeverity.ABORT, "Vision offset frame mismatch", Source.ASSUMED,
      "VOFFSET,VR[i] moves to a position taught in another user frame than the vision process's offset frame.",
      "Teach the position in the vision process's user frame (UFRAME_NUM=n before the motion), or change the "
          + "process's userFrame in the scenario."),

  // ---- RobotRun's own (no controller code fits, or none could be verified) --------------------
  SIMU_001("SIMU-001", AlarmSeverity.ABORT, "Divide by zero", Source.OWN,
      "The line divides by zero ('/', DIV or MOD with a zero divisor). (A controller raises an INTP alarm here; its "
          + "number could not be verified, so RobotRun uses its own.)",
      "Check the register the divisor comes from; guard the division with an IF."),
  SIMU_002("SIMU-002", AlarmSeverity.ABORT, "Statement structure", Source.OWN,
      "FOR without ENDFOR, ELSE or ENDIF without IF...THEN, a SELECT case outside a SELECT, or a CALL into a broken "
          + "program. (A controller refuses such a program when it is loaded.)",
      "Fix the block structure the message names; `robotrun check` lists every such line."),
  SIMU_003("SIMU-003", AlarmSeverity.ABORT, "Runaway loop", Source.OWN,
      "The program ran a very large number of lines in one tick without moving or waiting: an endless loop. "
          + "(A controller would just loop; the simulator stops it so the window stays usable.)",
      "Add a WAIT or a motion to the loop, or fix its exit condition."),
  SIMU_004("SIMU-004", AlarmSeverity.ABORT, "Write protected", Source.OWN,
      "The program assigned an input (DI, RI, GI), which only the outside world sets. "
          + "(A controller refuses the line when it is entered.)",
      "Write to an output (DO, RO, GO) instead."),
  SIMU_005("SIMU-005", AlarmSeverity.ABORT, "Program aborted", Source.OWN,
      "The program ran an ABORT instruction and ended. (A controller ends the program without an alarm; RobotRun "
          + "shows one so a grader can see why it ended.)",
      "Nothing to fix if the program meant to end; otherwise check why it reached ABORT."),
  SIMU_006("SIMU-006", AlarmSeverity.ABORT, "Circular path invalid", Source.OWN,
      "The three points of a circular move (start, via, target) lie on one line or two are the same, so no circle "
          + "passes through them.",
      "Teach the via point off the line between start and target."),
  SIMU_007("SIMU-007", AlarmSeverity.ABORT, "Frame number mismatch", Source.OWN,
      "The position was taught in a user or tool frame (UF/UT) other than the active ones. (A controller raises an "
          + "INTP alarm here; its number could not be verified.)",
      "Select the frames the position was taught in (UFRAME_NUM / UTOOL_NUM), or re-teach it in the active ones."),
  SIMU_008("SIMU-008", AlarmSeverity.ABORT, "Invalid speed or ACC", Source.OWN,
      "The move's speed or ACC value cannot be used (out of range for its unit).",
      "Change the speed or ACC on the line to a value in range."),
  SIMU_009("SIMU-009", AlarmSeverity.ABORT, "Invalid offset", Source.OWN,
      "An Offset or Tool_Offset uses a joint PR where a Cartesian one is needed.",
      "Store the offset as a Cartesian PR (X, Y, Z, W, P, R)."),
  SIMU_010("SIMU-010", AlarmSeverity.ABORT, "Motion queue busy", Source.OWN,
      "A move was asked while another one was already waiting to start.",
      "Wait for the arm to finish (or HOLD and ABORT) before giving another move."),
  SIMU_011("SIMU-011", AlarmSeverity.ABORT, "Motion failed", Source.OWN,
      "The motion planner refused a move for a reason it could not name more precisely.",
      "RESET, then check the target position and the frames it was taught in."),
  SIMU_012("SIMU-012", AlarmSeverity.ABORT, "Not supported in RobotRun", Source.OWN,
      "The line is a valid controller instruction that the simulator reads and keeps but cannot run (e.g. "
          + "RUN, TOOL_OFFSET CONDITION, a monitor's action program that moves). A controller would run it.",
      "Leave the line out of programs you run in RobotRun, or run this part on a real controller; `robotrun check` "
          + "lists such lines."),
  RUN_001("RUN-001", AlarmSeverity.ABORT, "Time limit", Source.OWN,
      "`robotrun run` stopped the program because it ran longer than --max-sim-seconds of simulated time (a "
          + "headless-run limit; no controller has it).",
      "Look for a WAIT that never ends or an endless loop; raise --max-sim-seconds if the program is just long."),
  RUN_002("RUN-002", AlarmSeverity.ABORT, "Wall-clock limit", Source.OWN,
      "`robotrun run` stopped because the run took longer than --max-wall-seconds of real time (a safety net for "
          + "graders; no controller has it).",
      "Look for a program that runs very long; raise --max-wall-seconds if the machine is just slow.");

  /** How a code was checked against the controller. */
  public enum Source {
    /** Code and text checked against a copy of FANUC's alarm documentation (docs/alarms.md cites it). */
    VERIFIED,
    /** The controller's code as the R-30iB alarm code manual gives it, from memory; no copy could be checked here. */
    RECALLED,
    /**
     * A code of the controller's family (CVIS) chosen for the fault; the number could not be checked
     * against the controller's alarm manual here (docs/alarms.md lists these as assumed).
     */
    ASSUMED,
    /**
   * RobotRun's own alarm ({@code SIMU-nnn}; {@code RUN-nnn} for the headless runner): no
   * controller code fits or none could be verified.
   */
    OWN
  }

  private final String code;
  private final AlarmSeverity severity;
  private final String text;
  private final Source source;
  private final String cause;
  private final String remedy;

  AlarmCode(String code, AlarmSeverity severity, String text, Source source, String cause, String remedy) {
    this.code = code;
    this.severity = severity;
    this.text = text;
    this.source = source;
    this.cause = cause;
    this.remedy = remedy;
  }

  /** The code shown on the pendant, e.g. {@code INTP-224}. */
  public String code() {
    return code;
  }

  public AlarmSeverity severity() {
    return severity;
  }

  /** The controller's alarm text, e.g. "Jump label is fail". */
  public String text() {
    return text;
  }

  public Source source() {
    return source;
  }

  /** Why it happens, for students. */
  public String cause() {
    return cause;
  }

  /** What to do, for students. */
  public String remedy() {
    return remedy;
  }

  /** The row for {@code code} ("INTP-224"), if the table has one. */
  public static Optional<AlarmCode> of(String code) {
    return Optional.ofNullable(BY_CODE.get(code));
  }

  /** Rows by code: {@link #of} is asked every tick (servo-off alarms decide the UOP outputs). */
  private static final java.util.Map<String, AlarmCode> BY_CODE = Arrays.stream(values())
      .collect(java.util.stream.Collectors.toUnmodifiableMap(AlarmCode::code, a -> a));
}
