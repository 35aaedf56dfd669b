package org.robotrun.program;

import java.util.OptionalDouble;
import org.robotrun.program.Nodes.Idx;
import org.robotrun.program.Nodes.Node;

/**
 * Compiled lines: one {@link Op} per /MN line, built by {@link Compiler}. Before {@code exec}
 * the interpreter has already advanced the frame's program counter to the next line; an op that
 * branches overwrites it. {@code exec} answers {@link #NEXT} to go on or {@link #HALT} when the
 * interpreter must stop this tick (it has then set its state and outcome).
 */
final class Ops {
  private Ops() {}

  static final int NEXT = 0;
  static final int HALT = 1;

  abstract static class Op {
    abstract int exec(Interpreter m);
  }

  /** Comment, //, blank line, LBL, PAYLOAD (after its range check), ENDIF. */
  static final class Nop extends Op {
    @Override
    int exec(Interpreter m) {
      return NEXT;
    }
  }

  /** A line that alarms when run (e.g. a direct index out of range found at compile time). */
  static final class Fail extends Op {
    final AlarmKind kind;
    final String message;

    Fail(AlarmKind kind, String message) {
      this.kind = kind;
      this.message = message;
    }

    @Override
    int exec(Interpreter m) {
      throw new AlarmSignal(kind, message);
    }
  }

  /** {@code R[n]=expr} with n checked at compile time: the hot path. */
  static final class AssignRDirect extends Op {
    final int i;
    final Node value;

    AssignRDirect(int i, Node value) {
      this.i = i;
      this.value = value;
    }

    @Override
    int exec(Interpreter m) {
      double v = value.eval(m);
      m.storeR(i, v);
      return NEXT;
    }
  }

  /** {@code MONITOR NAME} / {@code MONITOR END NAME}. */
  static final class MonitorOp extends Op {
    final String program;
    final boolean end;

    MonitorOp(String program, boolean end) {
      this.program = program;
      this.end = end;
    }

    @Override
    int exec(Interpreter m) {
      if (end) {
        m.monitorEnd(program);
      } else {
        m.monitorStart(program);
      }
      return NEXT;
    }
  }

  /** {@code SR[i]=expr}: a number is stored as its text. */
  static final class AssignSrOp extends Op {
    final Idx idx;
    final Node value;

    AssignSrOp(Idx idx, Node value) {
      this.idx = idx;
      this.value = value;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check("SR", idx.resolve(m), Registers.SR_COUNT);
      String t = Nodes.text(m, value.eval(m), "SR[" + i + "]");
      if (t.length() > Registers.SR_LENGTH) {
        throw new AlarmSignal(AlarmKind.BAD_VALUE, "SR[" + i + "]: at most " + Registers.SR_LENGTH
            + " characters, got " + t.length());
      }
      m.regs.setString(i, t);
      return NEXT;
    }
  }

  /** {@code R[R[j]]=expr}. */
  static final class AssignRIndexed extends Op {
    final Idx idx;
    final Node value;

    AssignRIndexed(Idx idx, Node value) {
      this.idx = idx;
      this.value = value;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check("R", idx.resolve(m), Registers.R_COUNT);
      double v = value.eval(m);
      m.storeR(i, v);
      return NEXT;
    }
  }

  /** A label target: resolved at compile time when direct, looked up when indirect. */
  static final class LabelTarget {
    final Idx idx;
    /** Line index of a direct label, -1 when the program has no such label or it is indirect. */
    final int directLine;

    LabelTarget(Idx idx, int directLine) {
      this.idx = idx;
      this.directLine = directLine;
    }

    int line(Interpreter m) {
      if (directLine >= 0) {
        return directLine;
      }
      int n = idx.resolve(m);
      int line = m.cur.prog.labelLine(n);
      if (line < 0) {
        throw new AlarmSignal(AlarmKind.UNKNOWN_LABEL, "LBL[" + n + "] is not in program " + m.cur.prog.name);
      }
      return line;
    }
  }

  /** A JMP or CALL as the action of IF / SELECT. */
  abstract static class BranchOp extends Op {
    /** Takes the branch; {@code after} is where a CALL returns to. */
    abstract int take(Interpreter m, int after);

    @Override
    int exec(Interpreter m) {
      return take(m, m.cur.pc);
    }
  }

  static final class JumpOp extends BranchOp {
    final LabelTarget target;

    JumpOp(LabelTarget target) {
      this.target = target;
    }

    @Override
    int take(Interpreter m, int after) {
      m.cur.pc = target.line(m);
      return NEXT;
    }
  }

  static final class CallOp extends BranchOp {
    final String program;
    final Node[] args;

    CallOp(String program, Node[] args) {
      this.program = program;
      this.args = args;
    }

    @Override
    int take(Interpreter m, int after) {
      m.call(program, args, after);
      return NEXT;
    }
  }

  /**
   * A macro line: runs as a CALL of the program the macro table names; a one-word macro the
   * table does not hold runs the program of its own name (RobotRun's default table).
   */
  static final class MacroOp extends Op {
    final String name;
    final Node[] args;
    /** The table's key of the name, made once (not on every call). */
    final String key;

    MacroOp(String name, Node[] args) {
      this.name = name;
      this.args = args;
      this.key = InterpreterSettings.macroKey(name);
    }

    @Override
    int exec(Interpreter m) {
      String program = m.settings.macros().get(key);
      if (program == null) {
        if (key.contains(" ")) {
          throw new AlarmSignal(AlarmKind.UNKNOWN_PROGRAM, "macro " + key + ": not in the macro table");
        }
        program = name;
      }
      m.call(program, args, m.cur.pc);
      return NEXT;
    }
  }

  static final class IfOp extends Op {
    final Node condition;
    final BranchOp branch;

    IfOp(Node condition, BranchOp branch) {
      this.condition = condition;
      this.branch = branch;
    }

    @Override
    int exec(Interpreter m) {
      return condition.bool(m, "IF") ? branch.take(m, m.cur.pc) : NEXT;
    }
  }

  /** {@code IF cond,action}: runs the action's op when the condition holds. */
  static final class IfActionOp extends Op {
    final Node condition;
    final Op action;

    IfActionOp(Node condition, Op action) {
      this.condition = condition;
      this.action = action;
    }

    @Override
    int exec(Interpreter m) {
      return condition.bool(m, "IF") ? action.exec(m) : NEXT;
    }
  }

  /** {@code IF (cond) THEN}: when false, goes to the line after ELSE, or to ENDIF. */
  static final class IfThenOp extends Op {
    final Node condition;
    int falseLine;

    IfThenOp(Node condition) {
      this.condition = condition;
    }

    @Override
    int exec(Interpreter m) {
      if (!condition.bool(m, "IF")) {
        m.cur.pc = falseLine;
      }
      return NEXT;
    }
  }

  /** {@code ELSE} reached from the THEN branch: skip to ENDIF. */
  static final class ElseOp extends Op {
    int endIfLine;

    @Override
    int exec(Interpreter m) {
      m.cur.pc = endIfLine;
      return NEXT;
    }
  }

  /** A whole SELECT group, run at its first line; case lines are skipped when reached. */
  static final class SelectOp extends Op {
    final Idx register;
    Node[] values;
    BranchOp[] branches;
    /** The ELSE branch, or null when the group has none. */
    BranchOp otherwise;
    /** First line after the group. */
    int afterLine;

    SelectOp(Idx register) {
      this.register = register;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check("R", register.resolve(m), Registers.R_COUNT);
      double v = m.regs.r[i];
      for (int c = 0; c < values.length; c++) {
        double x = values[c].number(m, "SELECT value");
        if (x == v) {
          m.cur.pc = afterLine;
          return branches[c].take(m, afterLine);
        }
      }
      m.cur.pc = afterLine;
      return otherwise == null ? NEXT : otherwise.take(m, afterLine);
    }
  }

  /** A SELECT case or ELSE line reached directly (e.g. by a jump): skip the rest of the group. */
  static final class SelectSkipOp extends Op {
    int afterLine;

    @Override
    int exec(Interpreter m) {
      m.cur.pc = afterLine;
      return NEXT;
    }
  }

  static final class ForOp extends Op {
    final int line;
    final Idx counter;
    final Node start;
    final Node end;
    final boolean down;
    int afterEndFor;

    ForOp(int line, Idx counter, Node start, Node end, boolean down) {
      this.line = line;
      this.counter = counter;
      this.start = start;
      this.end = end;
      this.down = down;
    }

    @Override
    int exec(Interpreter m) {
      int reg = Nodes.check("R", counter.resolve(m), Registers.R_COUNT);
      int a = start.integer(m, "FOR start");
      int b = end.integer(m, "FOR end");
      m.regs.r[reg] = a;
      m.regs.rIsInteger[reg] = true;
      Interpreter.Frame f = m.cur;
      if (down ? a < b : a > b) {
        f.forReg[line] = 0;
        f.pc = afterEndFor;
      } else {
        f.forReg[line] = reg;
        f.forEnd[line] = b;
      }
      return NEXT;
    }
  }

  /**
   * {@code ENDFOR}: while the counter has not reached the end value, steps it by one and loops;
   * the counter is left at the end value when the loop exits.
   */
  static final class EndForOp extends Op {
    final int forLine;
    final boolean down;

    EndForOp(int forLine, boolean down) {
      this.forLine = forLine;
      this.down = down;
    }

    @Override
    int exec(Interpreter m) {
      Interpreter.Frame f = m.cur;
      int reg = f.forReg[forLine];
      if (reg == 0) {
        throw new AlarmSignal(AlarmKind.STRUCTURE, "ENDFOR reached but its FOR (line " + (forLine + 1) + ") is not running");
      }
      Registers g = m.regs;
      double v = g.r[reg];
      if (!g.rIsInteger[reg]) {
        throw new AlarmSignal(AlarmKind.TYPE_MISMATCH, "FOR counter R[" + reg + "] must hold an integer, got " + v);
      }
      int end = f.forEnd[forLine];
      if (down ? v > end : v < end) {
        g.r[reg] = down ? v - 1 : v + 1;
        f.pc = forLine + 1;
      } else {
        f.forReg[forLine] = 0;
      }
      return NEXT;
    }
  }

  static final class EndOp extends Op {
    @Override
    int exec(Interpreter m) {
      return m.end();
    }
  }

  static final class PauseOp extends Op {
    @Override
    int exec(Interpreter m) {
      return m.pauseProgram();
    }
  }

  static final class WaitTimeOp extends Op {
    final Node seconds;

    WaitTimeOp(Node seconds) {
      this.seconds = seconds;
    }

    @Override
    int exec(Interpreter m) {
      return m.waitTime(seconds.number(m, "WAIT"));
    }
  }

  static final class WaitConditionOp extends Op {
    final Node condition;
    /** Null when the WAIT has no TIMEOUT label. */
    final LabelTarget timeout;

    WaitConditionOp(Node condition, LabelTarget timeout) {
      this.condition = condition;
      this.timeout = timeout;
    }

    @Override
    int exec(Interpreter m) {
      return condition.bool(m, "WAIT") ? NEXT : m.waitCondition(this);
    }
  }

  static final class TimerOp extends Op {
    final Idx idx;
    final Instruction.TimerAction action;

    TimerOp(Idx idx, Instruction.TimerAction action) {
      this.idx = idx;
      this.action = action;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check("TIMER", idx.resolve(m), Registers.TIMER_COUNT);
      switch (action) {
        case START -> m.regs.startTimer(i);
        case STOP -> m.regs.stopTimer(i);
        case RESET -> m.regs.resetTimer(i);
      }
      return NEXT;
    }
  }

  static final class SetIoOp extends Op {
    final IoKind io;
    final Idx idx;
    final Node value;

    SetIoOp(IoKind io, Idx idx, Node value) {
      this.io = io;
      this.idx = idx;
      this.value = value;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check(io.name(), idx.resolve(m), m.regs.ioSize(io));
      if (!io.writable()) {
        throw new AlarmSignal(AlarmKind.WRITE_PROTECTED, io.name() + "[" + i + "] is an input");
      }
      double v = value.eval(m);
      int k = m.kind;
      if (io.group()) {
        if (k > Nodes.REAL || !Nodes.isWhole(v)) {
          throw k > Nodes.REAL ? Nodes.mismatch(io.name() + "[" + i + "] needs an integer", k)
              : new AlarmSignal(AlarmKind.TYPE_MISMATCH, io.name() + "[" + i + "] needs an integer, got " + v);
        }
        m.regs.io[io.ordinal()][i] = (int) v;
      } else {
        if (k == Nodes.STR) {
          throw Nodes.mismatch(io.name() + "[" + i + "] needs ON/OFF", k);
        }
        // DO[i]=R[j]: 0 is OFF, any other number ON (as on the controller).
        m.regs.io[io.ordinal()][i] = v != 0 ? 1 : 0;
      }
      return NEXT;
    }
  }

  static final class PulseOp extends Op {
    final IoKind io;
    final Idx idx;
    final OptionalDouble widthSec;

    PulseOp(IoKind io, Idx idx, OptionalDouble widthSec) {
      this.io = io;
      this.idx = idx;
      this.widthSec = widthSec;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check(io.name(), idx.resolve(m), m.regs.ioSize(io));
      if (!io.writable() || io.group()) {
        throw new AlarmSignal(io.writable() ? AlarmKind.TYPE_MISMATCH : AlarmKind.WRITE_PROTECTED,
            io.name() + "[" + i + "] cannot be pulsed");
      }
      m.pulse(io, i, widthSec.orElse(m.settings.defaultPulseSec()));
      return NEXT;
    }
  }

  static final class MessageOp extends Op {
    final String text;

    MessageOp(String text) {
      this.text = text;
    }

    @Override
    int exec(Interpreter m) {
      m.message(text);
      return NEXT;
    }
  }

  static final class UserAlarmOp extends Op {
    final Idx idx;

    UserAlarmOp(Idx idx) {
      this.idx = idx;
    }

    @Override
    int exec(Interpreter m) {
      int n = idx.resolve(m);
      String text = m.settings.userAlarmMessages().getOrDefault(n, "UALM[" + n + "]");
      throw new AlarmSignal(AlarmKind.USER_ALARM, text);
    }
  }

  /** {@code RUN NAME}: asks the controller to start NAME as a task of its own; this program goes on. */
  static final class RunOp extends Op {
    final String program;

    RunOp(String program) {
      this.program = program;
    }

    @Override
    int exec(Interpreter m) {
      java.util.Optional<String> refused = m.taskPort().run(program);
      if (refused.isPresent()) {
        throw new AlarmSignal(AlarmKind.RUN_FAILED, refused.get());
      }
      return NEXT;
    }
  }

  static final class AbortOp extends Op {
    @Override
    int exec(Interpreter m) {
      throw new AlarmSignal(AlarmKind.ABORTED, "ABORT");
    }
  }

  /** {@code $WAITTMOUT=…}, {@code $MCR.$GENOVERRIDE=…} (SystemVariables). */
  static final class SetSysVarOp extends Op {
    final String name;
    final Node value;

    SetSysVarOp(String name, Node value) {
      this.name = name;
      this.value = value;
    }

    @Override
    int exec(Interpreter m) {
      int v = value.integer(m, name);
      switch (name) {
        case SystemVariables.WAITTMOUT -> {
          if (v < 0 || v > SystemVariables.MAX_WAITTMOUT) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, name + "=" + v + ": expected 0.." + SystemVariables.MAX_WAITTMOUT);
          }
          m.waitTimeoutSec = v / 100.0;
        }
        case SystemVariables.GENOVERRIDE -> {
          if (v < 1 || v > 100) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, name + "=" + v + ": expected 1..100");
          }
          m.port.setOverridePct(v);
        }
        case SystemVariables.TOOLNUM, SystemVariables.FRAMENUM -> {
          Instruction.FrameKind kind = name.equals(SystemVariables.TOOLNUM) ? Instruction.FrameKind.TOOL
              : Instruction.FrameKind.USER;
          if (v < 0 || v > Interpreter.FRAME_COUNT) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, name + "=" + v + ": expected 0.." + Interpreter.FRAME_COUNT);
          }
          m.port.selectFrame(kind, v);
        }
        default -> throw new IllegalStateException("no system variable " + name);
      }
      return NEXT;
    }
  }

  /** SKIP CONDITION: remembered for the following motions with Skip,LBL[]. */
  static final class SkipConditionOp extends Op {
    final Node condition;

    SkipConditionOp(Node condition) {
      this.condition = condition;
    }

    @Override
    int exec(Interpreter m) {
      m.skipCondition = condition;
      return NEXT;
    }
  }

  /** OFFSET CONDITION PR[i]: remembered for the following motions with a plain Offset. */
  static final class OffsetConditionOp extends Op {
    final Item register;
    /** The user frame the offset is expressed in, null for the motion's own frame. */
    final Nodes.Idx userFrame;

    OffsetConditionOp(Item register, Nodes.Idx userFrame) {
      this.register = register;
      this.userFrame = userFrame;
    }

    @Override
    int exec(Interpreter m) {
      m.offsetCondition = register;
      m.offsetConditionFrame = -1;
      if (userFrame != null) {
        int j = userFrame.resolve(m);
        if (j < 0 || j > 10) {
          throw new AlarmSignal(AlarmKind.BAD_VALUE, "OFFSET CONDITION UFRAME[" + j + "]: expected 0..10");
        }
        m.offsetConditionFrame = j;
      }
      return NEXT;
    }
  }

  static final class OverrideOp extends Op {
    final Node percent;

    OverrideOp(Node percent) {
      this.percent = percent;
    }

    @Override
    int exec(Interpreter m) {
      int p = percent.integer(m, "OVERRIDE");
      if (p < 1 || p > 100) {
        throw new AlarmSignal(AlarmKind.BAD_VALUE, "OVERRIDE=" + p + "%: expected 1..100");
      }
      m.port.setOverridePct(p);
      return NEXT;
    }
  }

  static final class PayloadOp extends Op {
    final Idx idx;

    PayloadOp(Idx idx) {
      this.idx = idx;
    }

    @Override
    int exec(Interpreter m) {
      // Accepted without dynamics; only the schedule number is checked (PAYLOAD[1..10]).
      Nodes.check("PAYLOAD", idx.resolve(m), 10);
      return NEXT;
    }
  }

  static final class SelectFrameOp extends Op {
    final Instruction.FrameKind kind;
    final Idx number;

    SelectFrameOp(Instruction.FrameKind kind, Idx number) {
      this.kind = kind;
      this.number = number;
    }

    @Override
    int exec(Interpreter m) {
      int n = number.resolve(m);
      if (n < 0 || n > Interpreter.FRAME_COUNT) {
        throw new AlarmSignal(AlarmKind.BAD_VALUE, frameName(kind) + "_NUM=" + n + ": expected 0.." + Interpreter.FRAME_COUNT);
      }
      m.port.selectFrame(kind, n);
      return NEXT;
    }
  }

  static String frameName(Instruction.FrameKind kind) {
    return switch (kind) {
      case USER -> "UFRAME";
      case TOOL -> "UTOOL";
    };
  }

  static final class SetFrameOp extends Op {
    final Instruction.FrameKind kind;
    final Idx frame;
    final Idx pr;

    SetFrameOp(Instruction.FrameKind kind, Idx frame, Idx pr) {
      this.kind = kind;
      this.frame = frame;
      this.pr = pr;
    }

    @Override
    int exec(Interpreter m) {
      int n = Nodes.check(frameName(kind), frame.resolve(m), Interpreter.FRAME_COUNT);
      int i = Nodes.check("PR", pr.resolve(m), Registers.PR_COUNT);
      if (!(m.regs.pr[i] instanceof Position.Cartesian c)) {
        throw new AlarmSignal(AlarmKind.TYPE_MISMATCH, frameName(kind) + "[" + n + "]=PR[" + i + "]: PR[" + i + "] is a joint position");
      }
      m.port.setFrame(kind, n, c);
      return NEXT;
    }
  }

  static final class AssignPrOp extends Op {
    final Idx target;
    final Instruction.PosSource source;
    final Idx a;
    final Idx b;

    AssignPrOp(Idx target, Instruction.PosSource source, Idx a, Idx b) {
      this.target = target;
      this.source = source;
      this.a = a;
      this.b = b;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check("PR", target.resolve(m), Registers.PR_COUNT);
      Position p = switch (source) {
        case Instruction.FromPosReg s -> m.regs.pr[Nodes.check("PR", a.resolve(m), Registers.PR_COUNT)];
        case Instruction.FromLocal s -> m.localPosition(s.number()).position();
        case Instruction.CurrentLpos s -> m.port.currentLpos();
        case Instruction.CurrentJpos s -> m.port.currentJpos();
        case Instruction.FromFrame s -> m.port.frame(s.kind(),
            Nodes.check(frameName(s.kind()), a.resolve(m), Interpreter.FRAME_COUNT));
        case Instruction.PosArithmetic s -> arithmetic(m, s.add());
        case Instruction.PosSum s -> sum(m, s);
        case Instruction.FromVisionRegister s -> throw new IllegalStateException("compiled as VisionOps.PositionFromVr");
      };
      m.regs.pr[i] = p;
      return NEXT;
    }

    /** A sum of positions, element by element; the first term's configuration is kept. */
    private static Position sum(Interpreter m, Instruction.PosSum s) {
      Position acc = term(m, s.first());
      for (Instruction.PosTerm t : s.rest()) {
        Position y = term(m, t.term());
        if (acc instanceof Position.Cartesian cx && y instanceof Position.Cartesian cy) {
          acc = t.add() ? cx.plus(cy) : cx.minus(cy);
        } else if (acc instanceof Position.Joint jx && y instanceof Position.Joint jy) {
          acc = t.add() ? jx.plus(jy) : jx.minus(jy);
        } else {
          throw new AlarmSignal(AlarmKind.TYPE_MISMATCH,
              "position arithmetic mixes a Cartesian and a joint position (" + termName(t.term()) + ")");
        }
      }
      return acc;
    }

    private static Position term(Interpreter m, Instruction.PosSource s) {
      return switch (s) {
        case Instruction.FromPosReg f -> m.regs.pr[Nodes.check("PR", new Idx(f.register().index()).resolve(m), Registers.PR_COUNT)];
        case Instruction.FromLocal f -> m.localPosition(f.number()).position();
        case Instruction.CurrentLpos c -> m.port.currentLpos();
        case Instruction.CurrentJpos c -> m.port.currentJpos();
        default -> throw new IllegalStateException("not a position term: " + s);
      };
    }

    private static String termName(Instruction.PosSource s) {
      return switch (s) {
        case Instruction.FromPosReg f -> "PR[]";
        case Instruction.FromLocal f -> "P[" + f.number() + "]";
        case Instruction.CurrentLpos c -> "LPOS";
        case Instruction.CurrentJpos c -> "JPOS";
        default -> s.toString();
      };
    }

    private Position arithmetic(Interpreter m, boolean add) {
      int j = Nodes.check("PR", a.resolve(m), Registers.PR_COUNT);
      int k = Nodes.check("PR", b.resolve(m), Registers.PR_COUNT);
      Position x = m.regs.pr[j];
      Position y = m.regs.pr[k];
      if (x instanceof Position.Cartesian cx && y instanceof Position.Cartesian cy) {
        return add ? cx.plus(cy) : cx.minus(cy);
      }
      if (x instanceof Position.Joint jx && y instanceof Position.Joint jy) {
        return add ? jx.plus(jy) : jx.minus(jy);
      }
      throw new AlarmSignal(AlarmKind.TYPE_MISMATCH, "PR[" + j + "] and PR[" + k + "] are not both Cartesian or both joint");
    }
  }

  static final class AssignPrElementOp extends Op {
    final Idx target;
    final Idx elementIdx;
    final Node value;

    AssignPrElementOp(Idx target, Idx element, Node value) {
      this.target = target;
      this.elementIdx = element;
      this.value = value;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check("PR", target.resolve(m), Registers.PR_COUNT);
      int element = elementIdx.resolve(m);
      if (element < 1 || element > Position.ELEMENTS) {
        throw new AlarmSignal(AlarmKind.BAD_INDEX, "PR[" + i + "," + element + "]: element out of range (expected 1..6)");
      }
      double v = value.number(m, "PR[" + i + "," + element + "]");
      m.regs.pr[i] = m.regs.pr[i].withElement(element, v);
      return NEXT;
    }
  }

  /** A motion line; {@link Interpreter#startMotion} resolves and issues it. */
  static final class MoveOp extends Op {
    final Instruction.Move move;
    /** Skip,LBL[] target or null. */
    final LabelTarget skip;

    MoveOp(Instruction.Move move, LabelTarget skip) {
      this.move = move;
      this.skip = skip;
    }

    @Override
    int exec(Interpreter m) {
      return m.startMotion(this, false, null);
    }
  }
}
