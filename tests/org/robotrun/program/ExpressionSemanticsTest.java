package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.program.Expr.BinaryOp.ADD;
import static org.robotrun.program.Expr.BinaryOp.AND;
import static org.robotrun.program.Expr.BinaryOp.DIV;
import static org.robotrun.program.Expr.BinaryOp.DIVIDE;
import static org.robotrun.program.Expr.BinaryOp.EQ;
import static org.robotrun.program.Expr.BinaryOp.GT;
import static org.robotrun.program.Expr.BinaryOp.MOD;
import static org.robotrun.program.Expr.BinaryOp.MUL;
import static org.robotrun.program.Expr.BinaryOp.NE;
import static org.robotrun.program.Expr.BinaryOp.OR;
import static org.robotrun.program.Expr.BinaryOp.SUB;
import static org.robotrun.program.Tp.group;
import static org.robotrun.program.Tp.io;
import static org.robotrun.program.Tp.neg;
import static org.robotrun.program.Tp.not;
import static org.robotrun.program.Tp.num;
import static org.robotrun.program.Tp.off;
import static org.robotrun.program.Tp.on;
import static org.robotrun.program.Tp.op;
import static org.robotrun.program.Tp.prog;
import static org.robotrun.program.Tp.r;
import static org.robotrun.program.Tp.real;
import static org.robotrun.program.Tp.rr;
import static org.robotrun.program.Tp.setR;
import static org.robotrun.program.Tp.setRR;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Values and types of expressions as the interpreter computes them. */
class ExpressionSemanticsTest {

  /** Runs {@code R[1]=e} and returns the rig. */
  private static Rig eval(Expr e) {
    Rig rig = new Rig(prog("E", setR(1, e)));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    return rig;
  }

  @Test
  void parenthesesFollowPrecedenceTwoPlusThreeTimesFourIsFourteen() {
    // R[1]=(2+3*4) as the reader builds it: * binds tighter than +.
    Rig rig = eval(group(op(num(2), ADD, op(num(3), MUL, num(4)))));
    assertThat(rig.regs.number(1)).isEqualTo(14.0);
    assertThat(rig.regs.isInteger(1)).isTrue();
  }

  @Test
  void explicitGroupsOverridePrecedence() {
    Rig rig = eval(op(group(op(num(2), ADD, num(3))), MUL, num(4)));
    assertThat(rig.regs.number(1)).isEqualTo(20.0);
  }

  @ParameterizedTest(name = "{0} DIV {1} = {2}, {0} MOD {1} = {3}")
  @CsvSource({
      "7, 2, 3, 1",
      "-7, 2, -3, -1",
      "7, -2, -3, 1",
      "-7, -2, 3, -1",
      "6, 3, 2, 0",
      "1, 5, 0, 1",
      "-1, 5, 0, -1"})
  void divTruncatesTowardZeroAndModTakesTheSignOfTheDividend(int a, int b, int div, int mod) {
    Rig rig = new Rig(prog("E", setR(1, op(num(a), DIV, num(b))), setR(2, op(num(a), MOD, num(b)))));
    rig.run();
    assertThat(rig.regs.number(1)).isEqualTo(div);
    assertThat(rig.regs.number(2)).isEqualTo(mod);
    assertThat(rig.regs.isInteger(1)).isTrue();
    assertThat(rig.regs.isInteger(2)).isTrue();
  }

  @Test
  void realModKeepsTheDividendsSign() {
    Rig rig = eval(op(real(-7.5), MOD, num(2)));
    assertThat(rig.regs.number(1)).isEqualTo(-1.5);
    assertThat(rig.regs.isInteger(1)).isFalse();
  }

  @Test
  void slashAlwaysGivesARealEvenWhenExact() {
    Rig rig = new Rig(prog("E", setR(1, op(num(7), DIVIDE, num(2))), setR(2, op(num(4), DIVIDE, num(2)))));
    rig.run();
    assertThat(rig.regs.number(1)).isEqualTo(3.5);
    assertThat(rig.regs.isInteger(1)).isFalse();
    assertThat(rig.regs.number(2)).isEqualTo(2.0);
    assertThat(rig.regs.isInteger(2)).isFalse();
  }

  @Test
  void integersStayIntegersAndRealsSpread() {
    Rig rig = new Rig(prog("E",
        setR(1, op(num(3), ADD, num(4))),
        setR(2, op(num(3), ADD, real(0.5))),
        setR(3, op(r(1), SUB, num(10))),
        setR(4, neg(r(3)))));
    rig.run();
    assertThat(rig.regs.number(1)).isEqualTo(7);
    assertThat(rig.regs.isInteger(1)).isTrue();
    assertThat(rig.regs.number(2)).isEqualTo(3.5);
    assertThat(rig.regs.isInteger(2)).isFalse();
    assertThat(rig.regs.number(3)).isEqualTo(-3);
    assertThat(rig.regs.number(4)).isEqualTo(3);
    assertThat(rig.regs.isInteger(4)).isTrue();
  }

  @Test
  void integerOverflowBecomesReal() {
    Rig rig = eval(op(num(Integer.MAX_VALUE), ADD, num(1)));
    assertThat(rig.regs.number(1)).isEqualTo(2147483648.0);
    assertThat(rig.regs.isInteger(1)).isFalse();
  }

  @Test
  void comparisonsAndLogicGiveOnOffWhichStoresAsOneOrZero() {
    Rig rig = new Rig(prog("E",
        setR(1, group(op(op(num(3), GT, num(2)), AND, op(num(1), EQ, num(1))))),
        setR(2, group(op(op(num(3), GT, num(5)), OR, not(on())))),
        setR(3, group(op(io(IoKind.DI, 1), NE, off())))));
    rig.regs.setBit(IoKind.DI, 1, true);
    rig.run();
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.regs.number(2)).isEqualTo(0);
    assertThat(rig.regs.number(3)).isEqualTo(1);
  }

  @Test
  void indirectRegistersReadAndWriteThroughTheIndexRegister() {
    Rig rig = new Rig(prog("E",
        setR(5, num(7)),
        setR(10, num(42)),
        setR(1, rr(5)),
        setRR(5, num(99))));
    rig.regs.setInteger(5, 10);
    rig.run();
    // R[5] was 7 after line 1 → R[1]=R[7]=0; then R[R[5]]=R[7]=99.
    assertThat(rig.regs.number(1)).isEqualTo(0);
    assertThat(rig.regs.number(7)).isEqualTo(99);
  }

  @Test
  void wholeRealsServeAsIndices() {
    Rig rig = new Rig(prog("E", setR(2, op(num(6), DIVIDE, num(2))), setRR(2, num(5))));
    rig.run();
    assertThat(rig.regs.number(3)).isEqualTo(5);
  }
}
