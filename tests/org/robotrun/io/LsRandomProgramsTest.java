package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.program.Config;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.LabelRef;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * Programs built in memory (as the pendant builds them), with random statements and expression
 * trees: writing, reading and writing again gives the same bytes, and what is read is read the
 * same way again. Fixed seed.
 */
class LsRandomProgramsTest {

  private final Random rnd = new Random(20260122L);

  @Test
  void writeReadWriteIsStableForRandomPrograms() {
    for (int round = 0; round < 300; round++) {
      Program p = program("RND" + round);
      String written = LsWriter.write(p);
      LsReadResult r = LsReader.parse("rnd.ls", written);
      // Random expressions may break the controller's entry rules (a warning, issue 13); nothing else is reported.
      assertThat(r.diagnostics()).as("%s", written)
          .allMatch(d -> d.message().startsWith("the controller does not mix"));
      assertThat(r.program().lineCount()).isEqualTo(p.lineCount());
      assertThat(r.program().positions()).isEqualTo(p.positions());
      String again = LsWriter.write(r.program());
      assertThat(again).isEqualTo(written);
      assertThat(LsReader.parse("rnd.ls", again).program()).isEqualTo(r.program());
    }
  }

  private Program program(String name) {
    List<Instruction> lines = new ArrayList<>();
    lines.add(new Instruction.Label(1, comment()));
    int n = 5 + rnd.nextInt(40);
    for (int i = 0; i < n; i++) {
      switch (rnd.nextInt(4)) {
        case 0 -> lines.add(move());
        case 1 -> block(lines);
        default -> lines.add(statement());
      }
    }
    List<LocalPosition> positions = new ArrayList<>();
    for (int k = 1; k <= 3; k++) {
      Position pos = rnd.nextBoolean()
          ? new Position.Cartesian(mm(), mm(), mm(), deg(), deg(), deg(),
              new Config(rnd.nextBoolean(), rnd.nextBoolean(), rnd.nextBoolean(), rnd.nextInt(3) - 1, rnd.nextInt(3) - 1, rnd.nextInt(3) - 1))
          : new Position.Joint(deg(), deg(), deg(), deg(), deg(), deg());
      positions.add(new LocalPosition(k, comment(), rnd.nextInt(3), rnd.nextInt(3), pos));
    }
    return Program.of(name, lines, positions);
  }

  private double mm() {
    return (rnd.nextInt(2_000_000) - 1_000_000) / 1000.0;
  }

  private double deg() {
    return (rnd.nextInt(360_000) - 180_000) / 1000.0;
  }

  private String comment() {
    if (rnd.nextInt(3) == 0) {
      return "";
    }
    String alphabet = "ABCXYZ_09 ";
    StringBuilder sb = new StringBuilder();
    for (int i = 0; i < 1 + rnd.nextInt(8); i++) {
      sb.append(alphabet.charAt(rnd.nextInt(alphabet.length())));
    }
    return sb.toString();
  }

  private Index index() {
    return rnd.nextInt(4) == 0 ? new Index.Indirect(1 + rnd.nextInt(200), comment()) : new Index.Direct(1 + rnd.nextInt(64));
  }

  private Item item() {
    return new Item(index(), comment());
  }

  /** An I/O port within every kind's default range (RI/RO have 8). */
  private Item ioItem() {
    return new Item(rnd.nextInt(4) == 0 ? new Index.Indirect(1 + rnd.nextInt(200), comment())
        : new Index.Direct(1 + rnd.nextInt(8)), comment());
  }

  private Item direct() {
    return new Item(new Index.Direct(1 + rnd.nextInt(64)), comment());
  }

  private Item timer() {
    return new Item(new Index.Direct(1 + rnd.nextInt(10)), comment());
  }

  private LabelRef label() {
    return new LabelRef(new Index.Direct(1), comment());
  }

  private Expr expr(int depth) {
    int pick = depth <= 0 ? rnd.nextInt(8) : rnd.nextInt(12);
    return switch (pick) {
      case 0 -> new Expr.IntConst(rnd.nextInt(2001) - 1000);
      case 1 -> new Expr.RealConst((rnd.nextInt(200_001) - 100_000) / 100.0);
      case 2 -> new Expr.OnOff(rnd.nextBoolean());
      case 3 -> new Expr.Register(item());
      case 4 -> new Expr.PosElement(item(), 1 + rnd.nextInt(6));
      case 5 -> new Expr.Io(IoKind.values()[rnd.nextInt(IoKind.values().length)], ioItem());
      case 6 -> new Expr.Timer(timer());
      case 7 -> switch (rnd.nextInt(6)) {
        case 0 -> new Expr.SysVar(org.robotrun.program.SystemVariables.SUPPORTED.get(rnd.nextInt(2)));
        case 1 -> new Expr.StringReg(srItem());
        case 2 -> new Expr.StringFunc(Expr.StringFn.STRLEN, java.util.List.of(new Expr.StringReg(srItem())));
        case 3 -> new Expr.StringFunc(Expr.StringFn.SUBSTR, java.util.List.of(new Expr.StringReg(srItem()),
            new Expr.IntConst(1 + rnd.nextInt(5)), new Expr.Register(direct())));
        case 4 -> new Expr.StringFunc(Expr.StringFn.FINDSTR, java.util.List.of(new Expr.StringReg(srItem()),
            new Expr.StringConst("AB" + rnd.nextInt(10))));
        default -> new Expr.Arg(new Index.Direct(1 + rnd.nextInt(10)));
      };
      case 8 -> new Expr.Unary(Expr.UnaryOp.values()[rnd.nextInt(2)], expr(depth - 1));
      case 9 -> new Expr.Group(expr(depth - 1));
      default -> new Expr.Binary(Expr.BinaryOp.values()[rnd.nextInt(Expr.BinaryOp.values().length)], expr(depth - 1), expr(depth - 1));
    };
  }

  private Motion.Target target() {
    return rnd.nextBoolean() ? new Motion.Local(1 + rnd.nextInt(3), comment()) : new Motion.Register(item());
  }

  private Instruction move() {
    Motion.Type type = Motion.Type.values()[rnd.nextInt(4)];
    List<Motion.SpeedUnit> units = new ArrayList<>();
    for (Motion.SpeedUnit u : Motion.SpeedUnit.values()) {
      if (u.fits(type)) {
        units.add(u);
      }
    }
    Motion.SpeedUnit unit = units.get(rnd.nextInt(units.size()));
    // Constant speeds are in range (the reader refuses 0 and more than 100%).
    int most = unit == Motion.SpeedUnit.PERCENT ? 100 : 2000;
    Motion.SpeedValue v = rnd.nextBoolean()
        ? new Motion.SpeedConst(rnd.nextBoolean() ? 1 + rnd.nextInt(most) : (1 + rnd.nextInt(most * 10)) / 10.0)
        : new Motion.SpeedRegister(direct());
    Motion.Speed speed = new Motion.Speed(v, unit);
    Motion.Termination term = switch (rnd.nextInt(3)) {
      case 0 -> new Motion.Fine();
      case 1 -> new Motion.Cnt(rnd.nextInt(101));
      default -> new Motion.CntRegister(direct());
    };
    List<Motion.Option> options = new ArrayList<>();
    for (int i = 0; i < rnd.nextInt(3); i++) {
      options.add(switch (rnd.nextInt(7)) {
        case 0 -> new Motion.Offset();
        case 1 -> new Motion.OffsetPr(item());
        case 2 -> new Motion.ToolOffsetPr(item());
        case 3 -> new Motion.Acc(rnd.nextInt(151));
        case 4 -> new Motion.Skip(label());
        case 5 -> new Motion.Wjnt();
        default -> new Motion.Inc();
      });
    }
    return type == Motion.Type.C
        ? Instruction.Move.circular(target(), target(), speed, term, options)
        : Instruction.Move.of(type, target(), speed, term, options);
  }

  private Instruction.Branch branch() {
    if (rnd.nextBoolean()) {
      return new Instruction.Jump(label());
    }
    List<Expr> args = new ArrayList<>();
    for (int i = 0; i < rnd.nextInt(3); i++) {
      args.add(rnd.nextBoolean() ? new Expr.StringConst("PART_" + i) : expr(1));
    }
    return new Instruction.Call("SUB" + rnd.nextInt(3), args);
  }

  private void block(List<Instruction> lines) {
    switch (rnd.nextInt(3)) {
      case 0 -> {
        lines.add(new Instruction.IfThen(new Expr.Group(expr(2))));
        lines.add(statement());
        if (rnd.nextBoolean()) {
          lines.add(new Instruction.Else());
          lines.add(statement());
        }
        lines.add(new Instruction.EndIf());
      }
      case 1 -> {
        Expr from = rnd.nextBoolean() ? new Expr.IntConst(rnd.nextInt(10)) : new Expr.Register(direct());
        lines.add(new Instruction.For(direct(), from, rnd.nextBoolean(), new Expr.IntConst(rnd.nextInt(10) - 5)));
        lines.add(statement());
        lines.add(new Instruction.EndFor());
      }
      default -> {
        lines.add(new Instruction.Select(direct(), new Expr.IntConst(rnd.nextInt(5)), branch()));
        for (int i = 0; i < rnd.nextInt(3); i++) {
          lines.add(new Instruction.SelectCase(new Expr.IntConst(rnd.nextInt(5)), branch()));
        }
        if (rnd.nextBoolean()) {
          lines.add(new Instruction.SelectElse(branch()));
        }
      }
    }
  }

  private Instruction statement() {
    return switch (rnd.nextInt(26)) {
      case 0 -> new Instruction.AssignRegister(item(), expr(3));
      case 1 -> new Instruction.AssignPosReg(item(), switch (rnd.nextInt(6)) {
        case 0 -> new Instruction.FromPosReg(item());
        case 1 -> new Instruction.FromLocal(1 + rnd.nextInt(3), comment());
        case 2 -> new Instruction.CurrentLpos();
        case 3 -> new Instruction.CurrentJpos();
        case 4 -> new Instruction.FromFrame(rnd.nextBoolean() ? FrameKind.USER : FrameKind.TOOL, index());
        default -> new Instruction.PosArithmetic(item(), rnd.nextBoolean(), item());
      });
      case 2 -> new Instruction.AssignPosElement(item(), 1 + rnd.nextInt(6), expr(2));
      case 3 -> new Instruction.SelectFrame(rnd.nextBoolean() ? FrameKind.USER : FrameKind.TOOL,
          rnd.nextBoolean() ? new Index.Direct(rnd.nextInt(10)) : new Index.Indirect(1 + rnd.nextInt(200), comment()));
      case 4 -> new Instruction.SetFrame(rnd.nextBoolean() ? FrameKind.USER : FrameKind.TOOL, index(), item());
      case 5 -> new Instruction.Payload(index());
      case 6 -> new Instruction.Jump(rnd.nextBoolean() ? label() : new LabelRef(new Index.Indirect(3, comment()), comment()));
      case 7 -> (Instruction) branch();
      case 8 -> new Instruction.End();
      case 9 -> new Instruction.Pause();
      case 10 -> new Instruction.Abort();
      case 11 -> new Instruction.If(expr(2), branch());
      case 12 -> new Instruction.WaitTime(rnd.nextBoolean() ? new Expr.RealConst(rnd.nextInt(1000) / 100.0) : new Expr.Register(direct()));
      case 13 -> new Instruction.WaitCondition(expr(2), rnd.nextBoolean() ? Optional.of(label()) : Optional.empty());
      case 14 -> new Instruction.TimerSet(timer(), Instruction.TimerAction.values()[rnd.nextInt(3)]);
      case 15 -> new Instruction.SetIo(new IoKind[] {IoKind.DO, IoKind.RO, IoKind.GO, IoKind.F}[rnd.nextInt(4)], ioItem(), expr(2));
      case 16 -> new Instruction.Pulse(rnd.nextBoolean() ? IoKind.DO : IoKind.RO, ioItem(),
          rnd.nextBoolean() ? OptionalDouble.of(rnd.nextInt(100) / 10.0) : OptionalDouble.empty());
      case 17 -> new Instruction.Comment(" " + comment());
      case 18 -> new Instruction.CommentedOut("L P[1] 100mm/sec FINE");
      case 19 -> new Instruction.Message("Part " + comment());
      case 20 -> new Instruction.UserAlarm(new Index.Direct(1 + rnd.nextInt(10)));
      case 21 -> new Instruction.SetOverride(rnd.nextBoolean() ? new Expr.IntConst(1 + rnd.nextInt(100)) : new Expr.Register(direct()));
      case 22 -> new Instruction.Blank();
      case 23 -> new Instruction.SetSysVar(org.robotrun.program.SystemVariables.SUPPORTED.get(rnd.nextInt(2)), expr(1));
      case 24 -> new Instruction.AssignString(srItem(), rnd.nextBoolean() ? new Expr.StringConst("PART_" + rnd.nextInt(100))
          : expr(2));
      default -> new Instruction.Label(1 + nextLabel(), comment());
    };
  }

  private Item srItem() {
    return new Item(new Index.Direct(1 + rnd.nextInt(25)), comment());
  }

  private int labelCounter;

  /** Distinct numbers for extra LBL lines (LBL[1] is every jump's target). */
  private int nextLabel() {
    return ++labelCounter;
  }
}
