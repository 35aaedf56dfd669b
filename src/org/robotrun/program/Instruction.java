package org.robotrun.program;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;

/**
 * One numbered line of a program's /MN section, one record per TP statement
 * (TP-LANGUAGE.md). Line n of a program is {@code program.lines().get(n - 1)}; a circular
 * motion with its continuation line is one line, as on the pendant. Multi-line constructs
 * (IF…THEN/ELSE/ENDIF, SELECT cases, FOR/ENDFOR) are one record per line, exactly as FANUC
 * numbers them; the interpreter matches them up.
 */
public sealed interface Instruction {

  // ---- motion -----------------------------------------------------------------------------

  /**
   * {@code type target speed termination [options]}. For {@code C} motion {@code target} is the
   * via point (first line) and {@code circularEnd} the end point of the continuation line, which
   * carries {@code speed}, {@code termination} and {@code options}; for the other types
   * {@code circularEnd} is empty.
   */
  record Move(Motion.Type type, Motion.Target target, Optional<Motion.Target> circularEnd,
      Motion.Speed speed, Motion.Termination termination, List<Motion.Option> options) implements Instruction {
    public Move {
      Objects.requireNonNull(type, "type");
      Objects.requireNonNull(target, "target");
      Objects.requireNonNull(circularEnd, "circularEnd");
      Objects.requireNonNull(speed, "speed");
      Objects.requireNonNull(termination, "termination");
      options = Motion.copyOptions(options);
      if ((type == Motion.Type.C) != circularEnd.isPresent()) {
        throw new IllegalArgumentException("a C motion has an end point, other types none");
      }
    }

    /** A J, L or A motion. */
    public static Move of(Motion.Type type, Motion.Target target, Motion.Speed speed, Motion.Termination term,
        List<Motion.Option> options) {
      return new Move(type, target, Optional.empty(), speed, term, options);
    }

    /** A C motion through {@code via} to {@code end}. */
    public static Move circular(Motion.Target via, Motion.Target end, Motion.Speed speed, Motion.Termination term,
        List<Motion.Option> options) {
      return new Move(Motion.Type.C, via, Optional.of(end), speed, term, options);
    }
  }

  // ---- registers --------------------------------------------------------------------------

  /** {@code R[i]=expr}. */
  record AssignRegister(Item register, Expr value) implements Instruction {
    public AssignRegister {
      Objects.requireNonNull(register, "register");
      Objects.requireNonNull(value, "value");
    }
  }

  /**
   * {@code SR[i]=expr}: a string register. A number is stored as its text ({@code SR[1]=R[2]}),
   * {@code +} with a string concatenates ({@code SR[1]=SR[2]+R[3]}).
   */
  record AssignString(Item register, Expr value) implements Instruction {
    public AssignString {
      Objects.requireNonNull(register, "register");
      Objects.requireNonNull(value, "value");
    }
  }

  /** {@code PR[i]=source}. */
  record AssignPosReg(Item register, PosSource source) implements Instruction {
    public AssignPosReg {
      Objects.requireNonNull(register, "register");
      Objects.requireNonNull(source, "source");
    }
  }

  /**
   * {@code PR[i,j]=expr}; j = 1..6, a constant or {@code R[k]} (resolved, and range-checked, when
   * the line runs). The item comment is on {@code register}.
   */
  record AssignPosElement(Item register, Index element, Expr value) implements Instruction {
    public AssignPosElement {
      Objects.requireNonNull(register, "register");
      Objects.requireNonNull(element, "element");
      Objects.requireNonNull(value, "value");
    }

    public AssignPosElement(Item register, int element, Expr value) {
      this(register, Index.of(element), value);
    }
  }

  /** The right side of {@code PR[i]=…}. */
  sealed interface PosSource {}

  /** {@code PR[j]}. */
  record FromPosReg(Item register) implements PosSource {
    public FromPosReg {
      Objects.requireNonNull(register, "register");
    }
  }

  /** {@code P[j]}: a local position. */
  record FromLocal(int number, String comment) implements PosSource {
    public FromLocal {
      Objects.requireNonNull(comment, "comment");
    }
  }

  /** {@code LPOS}: the current Cartesian position in the active frames. */
  record CurrentLpos() implements PosSource {}

  /** {@code JPOS}: the current joint position. */
  record CurrentJpos() implements PosSource {}

  /** {@code UFRAME[n]} or {@code UTOOL[n]}: a frame's data; {@code comment} as in {@code UFRAME[2:TABLE]}. */
  record FromFrame(FrameKind kind, Index frame, String comment) implements PosSource {
    public FromFrame {
      Objects.requireNonNull(kind, "kind");
      Objects.requireNonNull(frame, "frame");
      Objects.requireNonNull(comment, "comment");
    }

    public FromFrame(FrameKind kind, Index frame) {
      this(kind, frame, "");
    }
  }

  /**
   * {@code PR[i]=LPOS-LPOS}, {@code PR[i]=PR[j]+PR[k]-LPOS}, {@code PR[i]=P[3]+PR[2]}: a sum of
   * positions beyond {@link PosArithmetic}'s two registers, element by element (XYZWPR or J1..J6)
   * as the controller adds them; the first term's configuration is kept. Each term is a
   * {@link FromPosReg}, {@link FromLocal}, {@link CurrentLpos} or {@link CurrentJpos}; Cartesian
   * and joint terms together are a type-mismatch alarm when the line runs.
   */
  record PosSum(PosSource first, List<PosTerm> rest) implements PosSource {
    public PosSum {
      Objects.requireNonNull(first, "first");
      rest = List.copyOf(rest);
      if (rest.isEmpty() || !isTerm(first) || !rest.stream().allMatch(t -> isTerm(t.term()))) {
        throw new IllegalArgumentException("a position sum needs two or more PR[], P[], LPOS or JPOS terms");
      }
    }

    /** The sources a sum may hold. */
    public static boolean isTerm(PosSource s) {
      return s instanceof FromPosReg || s instanceof FromLocal || s instanceof CurrentLpos || s instanceof CurrentJpos;
    }
  }

  /** {@code +term} or {@code -term} of a {@link PosSum}. */
  record PosTerm(boolean add, PosSource term) {
    public PosTerm {
      Objects.requireNonNull(term, "term");
    }
  }

  /**
   * {@code VR[j].OFFSET} ({@code foundPos} false: the offset a VOFFSET applies) or {@code
   * VR[j].FOUND_POS[1]} (true: where the part was found), read from a vision register.
   */
  record FromVisionRegister(Item vr, boolean foundPos) implements PosSource {
    public FromVisionRegister {
      Objects.requireNonNull(vr, "vr");
    }
  }

  /** {@code PR[j]+PR[k]} ({@code add}) or {@code PR[j]-PR[k]}. */
  record PosArithmetic(Item left, boolean add, Item right) implements PosSource {
    public PosArithmetic {
      Objects.requireNonNull(left, "left");
      Objects.requireNonNull(right, "right");
    }
  }

  // ---- frames and payload -----------------------------------------------------------------

  /** User frame or tool frame. */
  enum FrameKind {
    /** {@code UFRAME} / {@code UFRAME_NUM}. */
    USER,
    /** {@code UTOOL} / {@code UTOOL_NUM}. */
    TOOL
  }

  /**
   * {@code UFRAME_NUM=n|R[i]} or {@code UTOOL_NUM=n|R[i]} (0 = world / flange); {@code
   * groupWritten} when the line names motion group 1, {@code UTOOL_NUM[GP1]=1}, as a
   * multi-group controller lists it (the same statement for the one arm RobotRun moves).
   */
  record SelectFrame(FrameKind kind, Index number, boolean groupWritten) implements Instruction {
    public SelectFrame {
      Objects.requireNonNull(kind, "kind");
      Objects.requireNonNull(number, "number");
    }

    public SelectFrame(FrameKind kind, Index number) {
      this(kind, number, false);
    }
  }

  /** {@code UFRAME[n]=PR[i]} or {@code UTOOL[n]=PR[i]}; {@code comment} as in {@code UFRAME[2:TABLE]}. */
  record SetFrame(FrameKind kind, Index frame, String comment, Item register) implements Instruction {
    public SetFrame {
      Objects.requireNonNull(kind, "kind");
      Objects.requireNonNull(frame, "frame");
      Objects.requireNonNull(comment, "comment");
      Objects.requireNonNull(register, "register");
    }

    public SetFrame(FrameKind kind, Index frame, Item register) {
      this(kind, frame, "", register);
    }
  }

  /** {@code PAYLOAD[n]} or {@code PAYLOAD[n:comment]}: accepted, no dynamics. */
  record Payload(Index schedule, String comment) implements Instruction {
    public Payload {
      Objects.requireNonNull(schedule, "schedule");
      Objects.requireNonNull(comment, "comment");
    }

    public Payload(Index schedule) {
      this(schedule, "");
    }
  }

  // ---- flow -------------------------------------------------------------------------------

  /** What an {@code IF cond,} or a SELECT case does: a jump or a call. */
  sealed interface Branch {}

  /** {@code LBL[n:comment]}: a jump target (always a direct number). */
  record Label(int number, String comment) implements Instruction {
    public Label {
      Objects.requireNonNull(comment, "comment");
    }
  }

  /** {@code JMP LBL[n]} / {@code JMP LBL[R[i]]}. */
  record Jump(LabelRef label) implements Instruction, Branch {
    public Jump {
      Objects.requireNonNull(label, "label");
    }
  }

  /** {@code CALL NAME} / {@code CALL NAME(args)}: args land in AR[1..]. */
  record Call(String program, List<Expr> args) implements Instruction, Branch {
    public Call {
      Objects.requireNonNull(program, "program");
      args = List.copyOf(args);
    }
  }

  /**
   * {@code RUN NAME}: starts program NAME as a task of its own beside this one (multitasking);
   * this program goes on at once. Arguments are read and kept as written.
   */
  record Run(String program, List<Expr> args) implements Instruction {
    public Run {
      Objects.requireNonNull(program, "program");
      args = List.copyOf(args);
    }
  }

  /** {@code END}: return from a call; at top level ends the program. */
  record End() implements Instruction {}

  /** {@code PAUSE}. */
  record Pause() implements Instruction {}

  /** {@code ABORT}. */
  record Abort() implements Instruction {}

  /** {@code IF cond, JMP LBL[n]} / {@code IF cond, CALL NAME}. */
  record If(Expr condition, Branch branch) implements Instruction {
    public If {
      Objects.requireNonNull(condition, "condition");
      Objects.requireNonNull(branch, "branch");
    }
  }

  /** {@code IF (expr) THEN}; the condition is usually an {@link Expr.Group}. */
  /**
   * {@code IF cond,action}: the action runs when the condition holds ({@code IF DI[1]=ON,DO[2]=(ON)},
   * {@code IF R[1]>3,R[2]=(R[2]+1)}, {@code IF F[1],DO[3]=PULSE,0.5sec}). The controller allows
   * an assignment of R[], PR[i,j] or an output, or a pulse (FANUC R-30iB Operator's Manual,
   * "Conditional branch instructions", IF with an action).
   */
  record IfAction(Expr condition, Instruction action) implements Instruction {
    public IfAction {
      Objects.requireNonNull(condition, "condition");
      Objects.requireNonNull(action, "action");
      if (!allowedAction(action)) {
        throw new IllegalArgumentException("IF action must be an assignment, an output or a pulse: " + action);
      }
    }

    /** The statements an IF may run as its action. */
    public static boolean allowedAction(Instruction action) {
      return action instanceof AssignRegister || action instanceof SetIo || action instanceof Pulse
          || action instanceof AssignPosElement;
    }
  }

  record IfThen(Expr condition) implements Instruction {
    public IfThen {
      Objects.requireNonNull(condition, "condition");
    }
  }

  /** {@code ELSE} of an IF…THEN block. */
  record Else() implements Instruction {}

  /** {@code ENDIF}. */
  record EndIf() implements Instruction {}

  /** First line of a SELECT: {@code SELECT R[i]=value, branch}. */
  record Select(Item register, Expr value, Branch branch) implements Instruction {
    public Select {
      Objects.requireNonNull(register, "register");
      Objects.requireNonNull(value, "value");
      Objects.requireNonNull(branch, "branch");
    }
  }

  /** A further SELECT line: {@code =value, branch}. */
  record SelectCase(Expr value, Branch branch) implements Instruction {
    public SelectCase {
      Objects.requireNonNull(value, "value");
      Objects.requireNonNull(branch, "branch");
    }
  }

  /** The last SELECT line: {@code ELSE, branch}. */
  record SelectElse(Branch branch) implements Instruction {
    public SelectElse {
      Objects.requireNonNull(branch, "branch");
    }
  }

  /** {@code FOR R[i]=start TO|DOWNTO end}; start/end are constants, R[] or AR[]. */
  record For(Item counter, Expr start, boolean down, Expr end) implements Instruction {
    public For {
      Objects.requireNonNull(counter, "counter");
      Objects.requireNonNull(start, "start");
      Objects.requireNonNull(end, "end");
    }
  }

  /** {@code ENDFOR}. */
  record EndFor() implements Instruction {}

  /** {@code WAIT t(sec)} or {@code WAIT R[i]}: seconds of simulated time. */
  record WaitTime(Expr seconds) implements Instruction {
    public WaitTime {
      Objects.requireNonNull(seconds, "seconds");
    }
  }

  /**
   * {@code WAIT cond} or {@code WAIT cond TIMEOUT,LBL[n]}: waits until the condition holds; with a
   * timeout label jumps there after $WAITTMOUT seconds.
   */
  record WaitCondition(Expr condition, Optional<LabelRef> timeoutLabel) implements Instruction {
    public WaitCondition {
      Objects.requireNonNull(condition, "condition");
      Objects.requireNonNull(timeoutLabel, "timeoutLabel");
    }
  }

  /** What a TIMER statement does. */
  enum TimerAction {
    START, STOP, RESET
  }

  /** {@code TIMER[i]=START|STOP|RESET}. */
  record TimerSet(Item timer, TimerAction action) implements Instruction {
    public TimerSet {
      Objects.requireNonNull(timer, "timer");
      Objects.requireNonNull(action, "action");
    }
  }

  // ---- I/O --------------------------------------------------------------------------------

  /**
   * {@code DO[i]=ON|OFF|R[j]}, {@code RO[i]=…}, {@code GO[i]=n|R[j]}, {@code F[i]=ON|OFF|(expr)}.
   */
  record SetIo(IoKind kind, Item port, Expr value) implements Instruction {
    public SetIo {
      Objects.requireNonNull(kind, "kind");
      Objects.requireNonNull(port, "port");
      Objects.requireNonNull(value, "value");
    }
  }

  /**
   * {@code DO[i]=PULSE} or {@code DO[i]=PULSE,t sec} (also RO): ON for the width then OFF; without
   * a width the controller's default pulse width ($DEFPULSE) applies.
   */
  record Pulse(IoKind kind, Item port, OptionalDouble widthSec) implements Instruction {
    public Pulse {
      Objects.requireNonNull(kind, "kind");
      Objects.requireNonNull(port, "port");
      Objects.requireNonNull(widthSec, "widthSec");
    }
  }

  // ---- iRVision (docs/vision.md) ------------------------------------------------------------

  /** The vision process a VISION statement names: {@code 'NAME'}, or {@code SR[i]} holding the name when the line runs. */
  sealed interface VisionProcess {}

  /** {@code 'FIND_BLOCKS'}. */
  record VisionProcessName(String name) implements VisionProcess {
    public VisionProcessName {
      Objects.requireNonNull(name, "name");
    }
  }

  /** {@code SR[i]}: the process named by a string register's value when the line runs. */
  record VisionProcessInRegister(Item register) implements VisionProcess {
    public VisionProcessInRegister {
      Objects.requireNonNull(register, "register");
    }
  }

  /** {@code VISION RUN_FIND 'NAME'}: snaps and finds; the results wait for GET_OFFSET. */
  record VisionRunFind(VisionProcess process) implements Instruction {
    public VisionRunFind {
      Objects.requireNonNull(process, "process");
    }
  }

  /** {@code VISION GET_OFFSET 'NAME' VR[i] JMP,LBL[j]}: the next result into VR[i]; the jump when none is left. */
  record VisionGetOffset(VisionProcess process, Item vr, LabelRef label) implements Instruction {
    public VisionGetOffset {
      Objects.requireNonNull(process, "process");
      Objects.requireNonNull(vr, "vr");
      Objects.requireNonNull(label, "label");
    }
  }

  /** {@code VISION GET_NFOUND 'NAME' R[i]}: how many the last RUN_FIND found, into R[i]. */
  record VisionGetNFound(VisionProcess process, Item register) implements Instruction {
    public VisionGetNFound {
      Objects.requireNonNull(process, "process");
      Objects.requireNonNull(register, "register");
    }
  }

  /** The numeric fields of a vision register a program reads. */
  enum VisionField {
    /** {@code .MODELID}: which model the part matched. */
    MODELID,
    /** {@code .ENC}: the conveyor encoder count (0: no tracking). */
    ENC,
    /** {@code .MES[k]}: measurement k (1 is the score). */
    MES
  }

  /** {@code R[i]=VR[j].MODELID}, {@code .ENC} or {@code .MES[k]} ({@code element} k = 1..10 for MES, 0 otherwise). */
  record AssignFromVr(Item register, Item vr, VisionField field, int element) implements Instruction {
    public AssignFromVr {
      Objects.requireNonNull(register, "register");
      Objects.requireNonNull(vr, "vr");
      Objects.requireNonNull(field, "field");
      if (field == VisionField.MES ? element < 1 || element > 10 : element != 0) {
        throw new IllegalArgumentException("MES[k] takes k = 1..10, the other fields no element: " + field + " " + element);
      }
    }
  }

  // ---- other ------------------------------------------------------------------------------

  /** {@code ! text}. */
  record Comment(String text) implements Instruction {
    public Comment {
      Objects.requireNonNull(text, "text");
    }
  }

  /** {@code //text}: a commented-out line, kept verbatim (after the {@code //}). */
  record CommentedOut(String text) implements Instruction {
    public CommentedOut {
      Objects.requireNonNull(text, "text");
    }
  }

  /** {@code $WAITTMOUT=500}: sets a system variable RobotRun runs ({@link SystemVariables}). */
  record SetSysVar(String name, Expr value) implements Instruction {
    public SetSysVar {
      Objects.requireNonNull(name, "name");
      Objects.requireNonNull(value, "value");
    }
  }

  /**
   * {@code SKIP CONDITION cond}: the condition the following motions with {@code Skip,LBL[n]}
   * watch. It stays set until the next SKIP CONDITION or the program ends.
   */
  record SkipCondition(Expr condition) implements Instruction {
    public SkipCondition {
      Objects.requireNonNull(condition, "condition");
    }
  }

  /**
   * {@code OFFSET CONDITION PR[i]} or {@code OFFSET CONDITION PR[i],UFRAME[j]}: the offset a motion
   * with a plain {@code Offset} option applies (PR[i] is read when the motion starts; with UFRAME[j]
   * the offset is expressed in user frame j, 0 = world, and turned into the motion's frame). It stays set until the next OFFSET CONDITION or the
   * program ends.
   */
  record OffsetCondition(Item register, Optional<Index> userFrame) implements Instruction {
    public OffsetCondition {
      Objects.requireNonNull(register, "register");
      Objects.requireNonNull(userFrame, "userFrame");
    }

    /** {@code OFFSET CONDITION PR[i]}: the offset in the motion's own user frame. */
    public OffsetCondition(Item register) {
      this(register, Optional.empty());
    }
  }

  /**
   * A macro called by its name ({@code OPEN_HAND}, {@code Open hand 1}, {@code Program Status(13)}):
   * runs the program the macro table names (a one-word macro with no table entry: the program of
   * its own name) as a CALL with {@code args} as AR[1..].
   */
  record MacroCall(String name, List<Expr> args) implements Instruction {
    public MacroCall {
      Objects.requireNonNull(name, "name");
      args = List.copyOf(args);
    }

    public MacroCall(String name) {
      this(name, List.of());
    }
  }

  /**
   * {@code MONITOR NAME} (starts watching the WHEN conditions of condition program NAME) or
   * {@code MONITOR END NAME} (stops it).
   */
  record Monitor(String program, boolean end) implements Instruction {
    public Monitor {
      Objects.requireNonNull(program, "program");
    }
  }

  /**
   * {@code WHEN cond,CALL NAME}: a line of a condition program (sub-type Cond). While the program
   * is monitored, the action program runs when the condition turns true.
   */
  record When(Expr condition, Call action) implements Instruction {
    public When {
      Objects.requireNonNull(condition, "condition");
      Objects.requireNonNull(action, "action");
    }
  }

  /** {@code MESSAGE[text]}: shown on the user screen. */
  record Message(String text) implements Instruction {
    public Message {
      Objects.requireNonNull(text, "text");
    }
  }

  /** {@code UALM[i]}: raises user alarm i. */
  record UserAlarm(Index number, String comment) implements Instruction {
    public UserAlarm {
      Objects.requireNonNull(number, "number");
      Objects.requireNonNull(comment, "comment");
    }

    public UserAlarm(Index number) {
      this(number, "");
    }
  }

  /** {@code OVERRIDE=n%} / {@code OVERRIDE=R[i]}: sets the speed override (1..100). */
  record SetOverride(Expr percent) implements Instruction {
    public SetOverride {
      Objects.requireNonNull(percent, "percent");
    }
  }

  /** A blank line. */
  record Blank() implements Instruction {}

  /**
   * A statement the controller has and RobotRun does not run yet ({@code SKIP CONDITION},
   * {@code VISION SET_REFERENCE}, {@code COL DETECT ON} ...): kept as written so it is
   * written back unchanged, and reported once per kind as {@code not supported: what}.
   *
   * @param text the statement as written, without line number and closing {@code ;}
   * @param what the kind, as the message names it ({@code "SKIP CONDITION"})
   * @param runnable true when the program can still run without it (the line is skipped and
   *     {@code check} warns); false when running past it would be wrong (the line alarms and
   *     {@code check} reports an error)
   */
  record Unsupported(String text, String what, boolean runnable) implements Instruction {
    public Unsupported {
      Objects.requireNonNull(text, "text");
      Objects.requireNonNull(what, "what");
    }

    /** An {@code IF ... THEN} line (its condition not supported): it still opens the block its ENDIF closes. */
    public boolean opensIfThen() {
      String t = text.strip().toUpperCase(java.util.Locale.ROOT);
      return t.startsWith("IF") && (t.length() == 2 || !Character.isLetterOrDigit(t.charAt(2))) && t.endsWith("THEN")
          && (t.length() == 4 || !Character.isLetterOrDigit(t.charAt(t.length() - 5)));
    }

    /** A {@code FOR} line (a bound not supported): it still opens the block its ENDFOR closes. */
    public boolean opensFor() {
      String t = text.strip().toUpperCase(java.util.Locale.ROOT);
      return t.startsWith("FOR ");
    }
  }
}
