package org.robotrun.program;

import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Nodes.Idx;
import org.robotrun.program.Ops.LabelTarget;
import org.robotrun.program.Ops.Op;

/** Compiled iRVision lines (docs/vision.md): RUN_FIND, GET_OFFSET, GET_NFOUND, VR reads, VOFFSET. */
final class VisionOps {
  private VisionOps() {}

  static AlarmSignal alarm(AlarmCode code, String message) {
    return new AlarmSignal(AlarmKind.VISION, code.code(), message);
  }

  /** VR[i] checked against 1..10 (CVIS-016). */
  static int vrIndex(Interpreter m, Idx idx) {
    int i = idx.resolve(m);
    if (i < 1 || i > VisionRegisters.COUNT) {
      throw alarm(AlarmCode.CVIS_016, "VR[" + i + "]: vision register index out of range (1.." + VisionRegisters.COUNT + ")");
    }
    return i;
  }

  /** VR[i]'s result; CVIS-017 when GET_OFFSET never filled it. */
  static VisionResult filled(Interpreter m, Idx idx) {
    int i = vrIndex(m, idx);
    return m.regs.vision().get(i).orElseThrow(() -> alarm(AlarmCode.CVIS_017, "VR[" + i
        + "] holds no vision result (run VISION GET_OFFSET into it first)"));
  }

  /**
   * The vision process a statement names: a constant name, or SR[i]'s value when the line runs
   * (CVIS-015 when the cell has no process of that name).
   */
  static final class Process {
    private final String name;
    private final Idx register;

    Process(Instruction.VisionProcess p) {
      switch (p) {
        case Instruction.VisionProcessName n -> {
          name = n.name();
          register = null;
        }
        case Instruction.VisionProcessInRegister r -> {
          name = null;
          register = new Idx(r.register().index());
        }
      }
    }

    String resolve(Interpreter m) {
      String n = name != null ? name : m.regs.string(Nodes.check("SR", register.resolve(m), Registers.SR_COUNT));
      if (!m.vision.hasProcess(n)) {
        throw alarm(AlarmCode.CVIS_015, "vision process '" + n + "' not found"
            + (name != null ? "" : " (the name SR[" + register.resolve(m) + "] holds)"));
      }
      return n;
    }
  }

  static final class RunFind extends Op {
    final Process proc;

    RunFind(Process proc) {
      this.proc = proc;
    }

    @Override
    int exec(Interpreter m) {
      String process = proc.resolve(m);
      switch (m.vision.runFind(process)) {
        case VisionPort.Outcome.Found f -> m.regs.vision().stored(process, f.results());
        case VisionPort.Outcome.Failed x -> throw new AlarmSignal(AlarmKind.VISION, x.code(), x.message());
      }
      return Ops.NEXT;
    }
  }

  static final class GetOffset extends Op {
    final Process proc;
    final Idx vr;
    final LabelTarget none;

    GetOffset(Process proc, Idx vr, LabelTarget none) {
      this.proc = proc;
      this.vr = vr;
      this.none = none;
    }

    @Override
    int exec(Interpreter m) {
      String process = proc.resolve(m);
      int i = vrIndex(m, vr);
      Optional<VisionResult> next = m.regs.vision().next(process);
      if (next == null) {
        throw alarm(AlarmCode.CVIS_018, "VISION GET_OFFSET '" + process + "' before its VISION RUN_FIND");
      }
      if (next.isEmpty()) {
        // Nothing (more) found: the jump, as on the controller; VR[i] keeps what it had.
        m.cur.pc = none.line(m);
        return Ops.NEXT;
      }
      m.regs.vision().set(i, next.get());
      return Ops.NEXT;
    }
  }

  static final class GetNFound extends Op {
    final Process proc;
    final Idx target;

    GetNFound(Process proc, Idx target) {
      this.proc = proc;
      this.target = target;
    }

    @Override
    int exec(Interpreter m) {
      String process = proc.resolve(m);
      int i = Nodes.check("R", target.resolve(m), Registers.R_COUNT);
      int n = m.regs.vision().found(process).orElseThrow(() -> alarm(AlarmCode.CVIS_018,
          "VISION GET_NFOUND '" + process + "' before its VISION RUN_FIND"));
      m.regs.r[i] = n;
      m.regs.rIsInteger[i] = true;
      return Ops.NEXT;
    }
  }

  static final class PositionFromVr extends Op {
    final Idx target;
    final Idx vr;
    final boolean foundPos;

    PositionFromVr(Idx target, Idx vr, boolean foundPos) {
      this.target = target;
      this.vr = vr;
      this.foundPos = foundPos;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check("PR", target.resolve(m), Registers.PR_COUNT);
      VisionResult r = filled(m, vr);
      m.regs.pr[i] = foundPos ? r.found() : r.offset();
      return Ops.NEXT;
    }
  }

  static final class NumberFromVr extends Op {
    final Idx target;
    final Idx vr;
    final Instruction.VisionField field;
    final int element;

    NumberFromVr(Idx target, Idx vr, Instruction.VisionField field, int element) {
      this.target = target;
      this.vr = vr;
      this.field = field;
      this.element = element;
    }

    @Override
    int exec(Interpreter m) {
      int i = Nodes.check("R", target.resolve(m), Registers.R_COUNT);
      VisionResult r = filled(m, vr);
      double v = switch (field) {
        case MODELID -> r.modelId();
        case ENC -> 0; // no conveyor tracking: the encoder count is 0
        case MES -> element == 1 ? r.score() : 0;
      };
      boolean integer = field != Instruction.VisionField.MES || v == Math.rint(v);
      m.regs.r[i] = v;
      m.regs.rIsInteger[i] = integer;
      return Ops.NEXT;
    }
  }

  /**
   * {@code VOFFSET,VR[i]} on a motion: the target becomes O · target with O the register's fixed
   * frame offset, both in the register's user frame. A position taught in another user frame is
   * refused (CVIS-019); a joint position cannot be offset (INTP-205).
   */
  static MotionRequest.Waypoint offset(Interpreter m, Idx vr, MotionRequest.Waypoint wp) {
    VisionResult r = filled(m, vr);
    if (!(wp.position() instanceof Position.Cartesian c)) {
      throw new AlarmSignal(AlarmKind.TYPE_MISMATCH, "VOFFSET needs a Cartesian position, " + wp.name() + " is a joint position");
    }
    if (wp.userFrame() != r.userFrame()) {
      throw alarm(AlarmCode.CVIS_019, "VOFFSET: " + wp.name() + " is in UF[" + wp.userFrame() + "] but VR[" + vr.resolve(m)
          + "] is an offset in UF[" + r.userFrame() + "]");
    }
    Transform X_UT = c.toXyzwpr().toTransform();
    Transform O = r.offset().toXyzwpr().toTransform();
    Position.Cartesian moved = Position.Cartesian.of(Xyzwpr.fromTransform(O.compose(X_UT)), c.config());
    return new MotionRequest.Waypoint(wp.name(), moved, wp.userFrame(), wp.toolFrame());
  }

  /** The op for a vision statement. */
  static Op of(Instruction in, java.util.function.Function<LabelRef, LabelTarget> label) {
    return switch (in) {
      case Instruction.VisionRunFind x -> new RunFind(new Process(x.process()));
      case Instruction.VisionGetOffset x -> new GetOffset(new Process(x.process()), new Idx(x.vr().index()),
          label.apply(x.label()));
      case Instruction.VisionGetNFound x -> new GetNFound(new Process(x.process()), new Idx(x.register().index()));
      case Instruction.AssignFromVr x -> new NumberFromVr(new Idx(x.register().index()), new Idx(x.vr().index()),
          x.field(), x.element());
      default -> throw new IllegalArgumentException("not a vision statement: " + in);
    };
  }
}
