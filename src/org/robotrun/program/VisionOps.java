package org.robotrun.program;

import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Nodes.Idx;
import org.robotrun.program.Ops.LabelTarget;
import org.robotrun.program.Ops.Op;

/** Compiled iRVision lines ({@link VisionStatement}): RUN_FIND, GET_OFFSET, GET_NFOUND, VR reads. */
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

  static void requireProcess(Interpreter m, String name) {
    if (!m.vision.hasProcess(name)) {
      throw alarm(AlarmCode.CVIS_015, "vision process '" + name + "' not found");
    }
  }

  static final class RunFind extends Op {
    final String process;

    RunFind(String process) {
      this.process = process;
    }

    @Override
    int exec(Interpreter m) {
      requireProcess(m, process);
      switch (m.vision.runFind(process)) {
        case VisionPort.Outcome.Found f -> m.regs.vision().stored(process, f.results());
        case VisionPort.Outcome.Failed x -> throw new AlarmSignal(AlarmKind.VISION, x.code(), x.message());
      }
      return Ops.NEXT;
    }
  }

  static final class GetOffset extends Op {
    final String process;
    final Idx vr;
    final LabelTarget none;

    GetOffset(String process, Idx vr, LabelTarget none) {
      this.process = process;
      this.vr = vr;
      this.none = none;
    }

    @Override
    int exec(Interpreter m) {
      requireProcess(m, process);
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
    final String process;
    final Idx target;

    GetNFound(String process, Idx target) {
      this.process = process;
      this.target = target;
    }

    @Override
    int exec(Interpreter m) {
      requireProcess(m, process);
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
    final VisionStatement.Field field;
    final int element;

    NumberFromVr(Idx target, Idx vr, VisionStatement.Field field, int element) {
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
      boolean integer = field != VisionStatement.Field.MES || v == Math.rint(v);
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
  static Op of(VisionStatement s, java.util.function.Function<LabelRef, LabelTarget> label) {
    return switch (s) {
      case VisionStatement.RunFind x -> new RunFind(x.process());
      case VisionStatement.GetOffset x -> new GetOffset(x.process(), new Idx(x.register()), label.apply(x.label()));
      case VisionStatement.GetNFound x -> new GetNFound(x.process(), new Idx(x.register()));
      case VisionStatement.PositionFromVr x -> new PositionFromVr(new Idx(x.target()), new Idx(x.vr()), x.foundPos());
      case VisionStatement.NumberFromVr x -> new NumberFromVr(new Idx(x.target()), new Idx(x.vr()), x.field(), x.element());
    };
  }

}
