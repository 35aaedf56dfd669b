package org.robotrun.program.bench;

import java.util.List;
import org.robotrun.program.Expr;
import org.robotrun.program.Instruction;
import org.robotrun.program.Interpreter;
import org.robotrun.program.InterpreterSettings;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.LabelRef;
import org.robotrun.program.MotionPort;
import org.robotrun.program.MotionRequest;
import org.robotrun.program.Outcome;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.ProgramStore;
import org.robotrun.program.Registers;

/**
 * The interpreter-throughput workload: a loop of typical non-motion statements (register
 * arithmetic with MOD and parentheses, IF…JMP, an output, labels), run for {@code loops}
 * iterations in one tick. Shared by the JMH benchmark and {@code robotrun bench interp}.
 *
 * <pre>
 *  1: R[1]=0
 *  2: LBL[1]
 *  3: R[1]=R[1]+1
 *  4: R[2]=(R[1] MOD 7)*3+R[4]
 *  5: IF R[2]>10,JMP LBL[2]
 *  6: R[3]=R[3]+R[2]
 *  7: LBL[2]
 *  8: DO[1]=ON
 *  9: IF R[1]&lt;R[5],JMP LBL[1]
 * 10: END
 * </pre>
 */
public final class InterpreterWorkload {
  private final Registers regs = new Registers();
  private final Interpreter interpreter;
  private final int loops;

  public InterpreterWorkload(int loops) {
    this.loops = loops;
    Program p = program();
    this.interpreter = new Interpreter(ProgramStore.of(p), regs, new NoMotion(),
        InterpreterSettings.defaults().withBudget(Integer.MAX_VALUE));
  }

  /** Lines one run executes: line 1, 7 or 8 per loop (line 6 runs for 4 of every 7 counts), line 10. */
  public long linesPerRun() {
    long taken = 0;
    for (int i = 1; i <= loops; i++) {
      taken += (i % 7) * 3 > 10 ? 1 : 0;
    }
    // Per loop: lines 2, 3, 4, 5, 7, 8, 9 always and line 6 when the jump is not taken.
    return 1 + 8L * loops - taken + 1;
  }

  /** Runs the program once from line 1 to END; returns the lines executed. */
  public long run() {
    regs.setInteger(5, loops);
    regs.setInteger(3, 0);
    long before = interpreter.executedLines();
    interpreter.select("BENCH");
    interpreter.forward();
    Outcome o = interpreter.tick(0);
    if (!(o instanceof Outcome.Finished)) {
      throw new IllegalStateException("benchmark program did not finish: " + o);
    }
    return interpreter.executedLines() - before;
  }

  /** R[3] after a run (consumed so the JIT cannot drop the work). */
  public double checksum() {
    return regs.number(3);
  }

  private static Program program() {
    Expr r1 = reg(1);
    Expr mod = new Expr.Group(new Expr.Binary(Expr.BinaryOp.MOD, r1, new Expr.IntConst(7)));
    Expr r2 = new Expr.Binary(Expr.BinaryOp.ADD, new Expr.Binary(Expr.BinaryOp.MUL, mod, new Expr.IntConst(3)), reg(4));
    return Program.of("BENCH", List.of(
        new Instruction.AssignRegister(Item.of(1), new Expr.IntConst(0)),
        new Instruction.Label(1, ""),
        new Instruction.AssignRegister(Item.of(1), new Expr.Binary(Expr.BinaryOp.ADD, r1, new Expr.IntConst(1))),
        new Instruction.AssignRegister(Item.of(2), r2),
        new Instruction.If(new Expr.Binary(Expr.BinaryOp.GT, reg(2), new Expr.IntConst(10)),
            new Instruction.Jump(LabelRef.of(2))),
        new Instruction.AssignRegister(Item.of(3), new Expr.Binary(Expr.BinaryOp.ADD, reg(3), reg(2))),
        new Instruction.Label(2, ""),
        new Instruction.SetIo(IoKind.DO, Item.of(1), new Expr.OnOff(true)),
        new Instruction.If(new Expr.Binary(Expr.BinaryOp.LT, r1, reg(5)), new Instruction.Jump(LabelRef.of(1))),
        new Instruction.End()));
  }

  private static Expr reg(int i) {
    return new Expr.Register(Item.of(i));
  }

  /** The workload has no motion; a port that refuses motions keeps it honest. */
  private static final class NoMotion implements MotionPort {
    @Override
    public Start startMotion(MotionRequest request) {
      return new Start.Rejected(org.robotrun.program.AlarmCode.SIMU_011.code(), "the benchmark has no robot");
    }

    @Override
    public Status poll(long handle) {
      return Status.FAILED;
    }

    @Override
    public Start.Rejected failure(long handle) {
      return new Start.Rejected(org.robotrun.program.AlarmCode.SIMU_011.code(), "the benchmark has no robot");
    }

    @Override
    public void hold(long handle) {}

    @Override
    public void resume(long handle) {}

    @Override
    public void cancel(long handle) {}

    @Override
    public Position.Cartesian currentLpos() {
      return Position.Cartesian.ZERO;
    }

    @Override
    public Position.Joint currentJpos() {
      return Position.Joint.ZERO;
    }

    @Override
    public int activeFrame(Instruction.FrameKind kind) {
      return 0;
    }

    @Override
    public void selectFrame(Instruction.FrameKind kind, int number) {}

    @Override
    public Position.Cartesian frame(Instruction.FrameKind kind, int number) {
      return Position.Cartesian.ZERO;
    }

    @Override
    public void setFrame(Instruction.FrameKind kind, int number, Position.Cartesian value) {}

    @Override
    public int overridePct() {
      return 100;
    }

    @Override
    public void setOverridePct(int percent) {}
  }
}
