package org.robotrun.program;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.robotrun.program.Nodes.Idx;
import org.robotrun.program.Nodes.Node;
import org.robotrun.program.Ops.LabelTarget;
import org.robotrun.program.Ops.Op;

/**
 * Turns a {@link Program} into a {@link CompiledProgram}: expressions into node trees, direct
 * labels into line indices, blocks matched. Problems that only matter when a line runs (an index
 * out of range, an unknown label) become alarms at run time, as on the controller; a broken block
 * structure is reported once, when the program starts or is called.
 */
final class Compiler {
  private final Program program;
  private final Map<Integer, Integer> labels = new TreeMap<>();
  private int errorLine = -1;
  private String error;

  private Compiler(Program program) {
    this.program = program;
  }

  static CompiledProgram compile(Program program) {
    return new Compiler(program).run();
  }

  private CompiledProgram run() {
    List<Instruction> lines = program.lines();
    int n = lines.size();
    for (int i = 0; i < n; i++) {
      if (lines.get(i) instanceof Instruction.Label l) {
        labels.putIfAbsent(l.number(), i);
      }
    }
    Op[] ops = new Op[n];
    boolean[] motion = new boolean[n];
    String[] blockers = new String[n];
    for (int i = 0; i < n; i++) {
      Instruction in = lines.get(i);
      ops[i] = line(i, in);
      motion[i] = in instanceof Instruction.Move;
      blockers[i] = backwardBlocker(in);
    }
    matchBlocks(lines, ops);
    int[] numbers = new int[labels.size()];
    int[] lineIdx = new int[labels.size()];
    int k = 0;
    for (Map.Entry<Integer, Integer> e : labels.entrySet()) {
      numbers[k] = e.getKey();
      lineIdx[k++] = e.getValue();
    }
    return new CompiledProgram(program, ops, motion, blockers, numbers, lineIdx, errorLine, error);
  }

  private void structureError(int line, String message) {
    if (error == null) {
      errorLine = line;
      error = message;
    }
  }

  /**
   * Backward execution passes over lines with no effect on motion order or the outside world
   * (comments, labels, register assignments…) and runs motion lines; every other statement stops
   * it (TP-LANGUAGE.md, "Execution"). Answers "" for a line it passes over, else the statement's
   * name for the message.
   */
  static String backwardBlocker(Instruction in) {
    return switch (in) {
      case Instruction.Comment c -> "";
      case Instruction.CommentedOut c -> "";
      case Instruction.Blank b -> "";
      case Instruction.Label l -> "";
      case Instruction.Message msg -> "";
      case Instruction.SetSysVar s -> "";
      case Instruction.AssignString a -> "";
      case Instruction.When w -> "";
      case Instruction.Monitor mo -> "MONITOR";
      case Instruction.MacroCall c -> "CALL";
      case Instruction.SkipCondition s -> "";
      case Instruction.OffsetCondition o -> "";
      case Instruction.Payload p -> "";
      case Instruction.AssignRegister a -> "";
      case Instruction.AssignPosReg a -> "";
      case Instruction.AssignPosElement a -> "";
      case Instruction.SelectFrame s -> "";
      case Instruction.SetFrame s -> "";
      case Instruction.TimerSet t -> "";
      case Instruction.SetOverride o -> "";
      case Instruction.Move mv -> "motion";
      case Instruction.Jump j -> "JMP";
      case Instruction.Call c -> "CALL";
      case Instruction.Run r -> "RUN";
      case Instruction.End e -> "END";
      case Instruction.Pause p -> "PAUSE";
      case Instruction.Abort a -> "ABORT";
      case Instruction.If f -> "IF";
      case Instruction.IfAction f -> "IF";
      case Instruction.IfThen f -> "IF…THEN";
      case Instruction.Else e -> "ELSE";
      case Instruction.EndIf e -> "ENDIF";
      case Instruction.Select s -> "SELECT";
      case Instruction.SelectCase s -> "SELECT";
      case Instruction.SelectElse s -> "SELECT";
      case Instruction.For f -> "FOR";
      case Instruction.EndFor e -> "ENDFOR";
      case Instruction.WaitTime w -> "WAIT";
      case Instruction.WaitCondition w -> "WAIT";
      case Instruction.SetIo s -> "I/O output";
      case Instruction.Pulse p -> "PULSE";
      case Instruction.VisionRunFind v -> "iRVision";
      case Instruction.VisionGetOffset v -> "iRVision";
      case Instruction.VisionGetNFound v -> "iRVision";
      case Instruction.AssignFromVr v -> "iRVision";
      case Instruction.Unsupported u -> u.what();
      case Instruction.UserAlarm u -> "UALM";
    };
  }

  private Op line(int i, Instruction in) {
    return switch (in) {
      case Instruction.Move mv -> new Ops.MoveOp(mv, skipLabel(mv));
      case Instruction.AssignRegister a -> assignR(a);
      case Instruction.AssignPosReg a -> assignPr(a);
      case Instruction.AssignPosElement a -> new Ops.AssignPrElementOp(idx(a.register().index()), idx(a.element()), expr(a.value()));
      case Instruction.SelectFrame s -> new Ops.SelectFrameOp(s.kind(), idx(s.number()));
      case Instruction.SetFrame s -> new Ops.SetFrameOp(s.kind(), idx(s.frame()), idx(s.register().index()));
      case Instruction.Payload p -> new Ops.PayloadOp(idx(p.schedule()));
      case Instruction.Label l -> new Ops.Nop();
      case Instruction.Jump j -> new Ops.JumpOp(label(j.label()));
      case Instruction.Call c -> call(c);
      case Instruction.Run r -> r.args().isEmpty() ? new Ops.RunOp(r.program())
          : new Ops.Fail(AlarmKind.NOT_SUPPORTED, "not supported in RobotRun: RUN with arguments");
      case Instruction.End e -> new Ops.EndOp();
      case Instruction.Pause p -> new Ops.PauseOp();
      case Instruction.Abort a -> new Ops.AbortOp();
      case Instruction.If f -> new Ops.IfOp(expr(f.condition()), branch(f.branch()));
      case Instruction.IfAction f -> new Ops.IfActionOp(expr(f.condition()), line(i, f.action()));
      case Instruction.IfThen f -> new Ops.IfThenOp(expr(f.condition()));
      case Instruction.Else e -> new Ops.ElseOp();
      case Instruction.EndIf e -> new Ops.Nop();
      case Instruction.Select s -> new Ops.SelectOp(idx(s.register().index()));
      case Instruction.SelectCase s -> new Ops.SelectSkipOp();
      case Instruction.SelectElse s -> new Ops.SelectSkipOp();
      case Instruction.For f -> new Ops.ForOp(i, idx(f.counter().index()), expr(f.start()), expr(f.end()), f.down());
      case Instruction.EndFor e -> new Ops.Nop(); // replaced when blocks are matched
      case Instruction.WaitTime w -> new Ops.WaitTimeOp(expr(w.seconds()));
      case Instruction.WaitCondition w -> new Ops.WaitConditionOp(expr(w.condition()),
          w.timeoutLabel().map(this::label).orElse(null));
      case Instruction.TimerSet t -> new Ops.TimerOp(idx(t.timer().index()), t.action());
      case Instruction.SetIo s -> new Ops.SetIoOp(s.kind(), idx(s.port().index()), expr(s.value()));
      case Instruction.Pulse p -> new Ops.PulseOp(p.kind(), idx(p.port().index()), p.widthSec());
      case Instruction.Comment c -> new Ops.Nop();
      case Instruction.CommentedOut c -> new Ops.Nop();
      case Instruction.Blank b -> new Ops.Nop();
      case Instruction.Message msg -> new Ops.MessageOp(msg.text());
      case Instruction.SetSysVar s -> new Ops.SetSysVarOp(s.name(), expr(s.value()));
      case Instruction.Monitor mo -> new Ops.MonitorOp(mo.program(), mo.end());
      // A WHEN line does nothing when run as a statement: it is watched through MONITOR.
      case Instruction.When w -> new Ops.Nop();
      case Instruction.AssignString a -> new Ops.AssignSrOp(idx(a.register().index()), expr(a.value()));
      case Instruction.MacroCall c -> new Ops.MacroOp(c.name(), c.args().stream().map(Compiler::expr).toArray(Node[]::new));
      case Instruction.SkipCondition s -> new Ops.SkipConditionOp(expr(s.condition()));
      case Instruction.OffsetCondition o -> new Ops.OffsetConditionOp(o.register(), o.userFrame().map(Compiler::idx).orElse(null));
      case Instruction.UserAlarm u -> new Ops.UserAlarmOp(idx(u.number()));
      case Instruction.SetOverride o -> new Ops.OverrideOp(expr(o.percent()));
      // Runnable kinds (settings, monitors) are skipped; running past the others would be wrong.
      case Instruction.VisionRunFind v -> VisionOps.of(v, this::label);
      case Instruction.VisionGetOffset v -> VisionOps.of(v, this::label);
      case Instruction.VisionGetNFound v -> VisionOps.of(v, this::label);
      case Instruction.AssignFromVr v -> VisionOps.of(v, this::label);
      case Instruction.Unsupported u -> u.runnable() ? new Ops.Nop()
          : new Ops.Fail(AlarmKind.NOT_SUPPORTED, "not supported in RobotRun: " + u.what());
    };
  }

  private LabelTarget skipLabel(Instruction.Move mv) {
    for (Motion.Option o : mv.options()) {
      if (o instanceof Motion.Skip s) {
        return label(s.label());
      }
    }
    return null;
  }

  private Op assignR(Instruction.AssignRegister a) {
    Node value = expr(a.value());
    if (a.register().index() instanceof Index.Direct d && d.value() >= 1 && d.value() <= Registers.R_COUNT) {
      return new Ops.AssignRDirect(d.value(), value);
    }
    return new Ops.AssignRIndexed(idx(a.register().index()), value);
  }

  private Op assignPr(Instruction.AssignPosReg a) {
    Idx target = idx(a.register().index());
    Instruction.PosSource s = a.source();
    return switch (s) {
      case Instruction.FromPosReg f -> new Ops.AssignPrOp(target, s, idx(f.register().index()), null);
      case Instruction.FromLocal f -> new Ops.AssignPrOp(target, s, null, null);
      case Instruction.CurrentLpos f -> new Ops.AssignPrOp(target, s, null, null);
      case Instruction.CurrentJpos f -> new Ops.AssignPrOp(target, s, null, null);
      case Instruction.FromFrame f -> new Ops.AssignPrOp(target, s, idx(f.frame()), null);
      case Instruction.PosArithmetic f -> new Ops.AssignPrOp(target, s, idx(f.left().index()), idx(f.right().index()));
      case Instruction.PosSum f -> new Ops.AssignPrOp(target, s, null, null);
      case Instruction.FromVisionRegister v -> new VisionOps.PositionFromVr(target, idx(v.vr().index()), v.foundPos());
    };
  }

  private Ops.BranchOp branch(Instruction.Branch b) {
    return switch (b) {
      case Instruction.Jump j -> new Ops.JumpOp(label(j.label()));
      case Instruction.Call c -> call(c);
    };
  }

  private Ops.CallOp call(Instruction.Call c) {
    Node[] args = new Node[c.args().size()];
    for (int k = 0; k < args.length; k++) {
      args[k] = expr(c.args().get(k));
    }
    return new Ops.CallOp(c.program(), args);
  }

  private LabelTarget label(LabelRef ref) {
    Idx idx = idx(ref.index());
    if (ref.index() instanceof Index.Direct d) {
      Integer line = labels.get(d.value());
      // An unknown direct label stays -1 and resolves (and alarms) when the jump runs.
      return new LabelTarget(idx, line == null ? -1 : line);
    }
    return new LabelTarget(idx, -1);
  }

  private static Idx idx(Index index) {
    return new Idx(index);
  }

  static Node expr(Expr e) {
    return switch (e) {
      case Expr.IntConst c -> new Nodes.Const(c.value(), Nodes.INT);
      case Expr.RealConst c -> new Nodes.Const(c.value(), Nodes.REAL);
      case Expr.OnOff c -> new Nodes.Const(c.on() ? 1 : 0, Nodes.BOOL);
      case Expr.StringConst c -> new Nodes.StrConst(c.value());
      case Expr.Register r -> r.register().index() instanceof Index.Direct d && d.value() >= 1
          && d.value() <= Registers.R_COUNT ? new Nodes.RegDirect(d.value()) : new Nodes.RegIndexed(idx(r.register().index()));
      case Expr.PosElement p -> new Nodes.PosElement(idx(p.register().index()), idx(p.element()));
      case Expr.Io io -> new Nodes.IoRead(io.kind(), idx(io.port().index()));
      case Expr.Timer t -> new Nodes.TimerRead(idx(t.timer().index()));
      case Expr.Arg a -> new Nodes.ArgRead(idx(a.index()));
      case Expr.SysVar v -> new Nodes.SysVarRead(v.name());
      case Expr.StringReg r -> new Nodes.SrRead(idx(r.register().index()));
      case Expr.StringFunc f -> new Nodes.StrFunc(f.fn(), f.args().stream().map(Compiler::expr).toArray(Node[]::new));
      case Expr.Unary u -> switch (u.op()) {
        case MINUS -> new Nodes.Neg(expr(u.operand()));
        case NOT -> new Nodes.Not(expr(u.operand()));
      };
      case Expr.Binary b -> binary(b.op(), expr(b.left()), expr(b.right()));
      case Expr.Group g -> expr(g.inner());
    };
  }

  private static Node binary(Expr.BinaryOp op, Node a, Node b) {
    return switch (op) {
      case ADD -> new Nodes.Add(a, b);
      case SUB -> new Nodes.Sub(a, b);
      case MUL -> new Nodes.Mul(a, b);
      case DIVIDE, DIV, MOD -> new Nodes.Division(op, a, b);
      case EQ, NE, LT, LE, GT, GE -> new Nodes.Compare(op, a, b);
      case AND -> new Nodes.Logic(true, a, b);
      case OR -> new Nodes.Logic(false, a, b);
    };
  }

  /** Matches FOR/ENDFOR and IF…THEN/ELSE/ENDIF (properly nested) and SELECT groups. */
  private void matchBlocks(List<Instruction> lines, Op[] ops) {
    Deque<Integer> open = new ArrayDeque<>();
    int[] elseOf = new int[lines.size()];
    java.util.Arrays.fill(elseOf, -1);
    // Only block statements matter here, so instanceof tests rather than a switch over every statement.
    for (int i = 0; i < lines.size(); i++) {
      Instruction in = lines.get(i);
      if (in instanceof Instruction.For || in instanceof Instruction.IfThen
          || in instanceof Instruction.Unsupported u && (u.opensIfThen() || u.opensFor())) {
        // An IF ... THEN or FOR kept as not supported still opens its block (the line alarms when it runs).
        open.push(i);
      } else if (in instanceof Instruction.EndFor && !open.isEmpty() && opensForUnsupported(lines.get(open.peek()))) {
        open.pop();
      } else if (in instanceof Instruction.EndFor) {
        if (open.isEmpty() || !(lines.get(open.peek()) instanceof Instruction.For f)) {
          structureError(i, "ENDFOR without FOR" + openBlock(lines, open));
          ops[i] = new Ops.Fail(AlarmKind.STRUCTURE, "ENDFOR without FOR");
        } else {
          int forLine = open.pop();
          ((Ops.ForOp) ops[forLine]).afterEndFor = i + 1;
          ops[i] = new Ops.EndForOp(forLine, f.down());
        }
      } else if (in instanceof Instruction.Else) {
        if (open.isEmpty() || !opensIf(lines.get(open.peek())) || elseOf[open.peek()] >= 0) {
          structureError(i, "ELSE without IF…THEN" + openBlock(lines, open));
          ops[i] = new Ops.Fail(AlarmKind.STRUCTURE, "ELSE without IF…THEN");
        } else {
          elseOf[open.peek()] = i;
        }
      } else if (in instanceof Instruction.EndIf) {
        if (open.isEmpty() || !opensIf(lines.get(open.peek()))) {
          structureError(i, "ENDIF without IF…THEN" + openBlock(lines, open));
        } else {
          int ifLine = open.pop();
          int elseLine = elseOf[ifLine];
          if (ops[ifLine] instanceof Ops.IfThenOp ifOp) {
            ifOp.falseLine = elseLine >= 0 ? elseLine + 1 : i;
          }
          if (elseLine >= 0) {
            ((Ops.ElseOp) ops[elseLine]).endIfLine = i;
          }
        }
      } else if (in instanceof Instruction.Select sel) {
        matchSelect(lines, ops, i, sel);
      } else if (in instanceof Instruction.SelectCase || in instanceof Instruction.SelectElse) {
        if (!(ops[i] instanceof Ops.SelectSkipOp skip && skip.afterLine > 0)) {
          structureError(i, "SELECT case without SELECT");
          ops[i] = new Ops.Fail(AlarmKind.STRUCTURE, "SELECT case without SELECT");
        }
      }
    }
    while (!open.isEmpty()) {
      int i = open.pop();
      boolean isFor = lines.get(i) instanceof Instruction.For;
      structureError(i, isFor ? "FOR without ENDFOR" : "IF…THEN without ENDIF");
    }
  }

  private static boolean opensIf(Instruction in) {
    return in instanceof Instruction.IfThen || in instanceof Instruction.Unsupported u && u.opensIfThen();
  }

  private static boolean opensForUnsupported(Instruction in) {
    return in instanceof Instruction.Unsupported u && u.opensFor();
  }

  private static String openBlock(List<Instruction> lines, Deque<Integer> open) {
    if (open.isEmpty()) {
      return "";
    }
    int i = open.peek();
    return " (innermost open block: " + (lines.get(i) instanceof Instruction.For || opensForUnsupported(lines.get(i)) ? "FOR" : "IF…THEN") + " at line " + (i + 1) + ")";
  }

  private void matchSelect(List<Instruction> lines, Op[] ops, int first, Instruction.Select s) {
    List<Node> values = new ArrayList<>();
    List<Ops.BranchOp> branches = new ArrayList<>();
    values.add(expr(s.value()));
    branches.add(branch(s.branch()));
    Ops.BranchOp otherwise = null;
    int i = first + 1;
    for (; i < lines.size(); i++) {
      Instruction in = lines.get(i);
      if (in instanceof Instruction.SelectCase c) {
        values.add(expr(c.value()));
        branches.add(branch(c.branch()));
      } else if (in instanceof Instruction.SelectElse e) {
        otherwise = branch(e.branch());
        i++;
        break;
      } else {
        break;
      }
    }
    Ops.SelectOp op = (Ops.SelectOp) ops[first];
    op.values = values.toArray(Node[]::new);
    op.branches = branches.toArray(Ops.BranchOp[]::new);
    op.otherwise = otherwise;
    op.afterLine = i;
    for (int k = first + 1; k < i; k++) {
      ((Ops.SelectSkipOp) ops[k]).afterLine = i;
    }
  }
}
