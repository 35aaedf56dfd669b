package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Position register arithmetic, element by element (docs/tp-language.md, "Registers, positions and
 * frames"): {@code PR[i]=PR[j]+PR[k]} and {@code -}, sums with P[n], LPOS and JPOS (the first term's
 * CONFIG kept), {@code PR[i,j]} read and written for j = 1..6 (X..R or J1..J6), each element with
 * its own value so that a swapped or dropped element shows. Expected values are the test's own
 * element sums.
 */
class PositionArithmeticTableTest {

  private static final double[] A = {11, -23, 37, 41, -53, 67};
  private static final double[] B = {2, 3, -5, 7, 11, -13};
  private static final Config FLIP = new Config(true, false, false, 1, -1, 0);

  private static Position.Cartesian cart(double[] v, Config c) {
    return new Position.Cartesian(v[0], v[1], v[2], v[3], v[4], v[5], c);
  }

  private static Position.Joint joint(double[] v) {
    return new Position.Joint(v[0], v[1], v[2], v[3], v[4], v[5]);
  }

  private static double[] elements(Position p) {
    double[] e = new double[6];
    for (int j = 1; j <= 6; j++) {
      e[j - 1] = p.element(j);
    }
    return e;
  }

  private static double[] sum(double[] a, double[] b, int sign) {
    double[] r = new double[6];
    for (int j = 0; j < 6; j++) {
      r[j] = a[j] + sign * b[j];
    }
    return r;
  }

  private static Rig run(Program p, Position pr2, Position pr3) {
    Rig rig = new Rig(p);
    rig.regs.setPosition(2, pr2);
    rig.regs.setPosition(3, pr3);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    return rig;
  }

  @Test
  void sumsAndDifferencesOfCartesianAndJointRegistersElementByElement() {
    Program p = RunSemanticsTableTest.parse("PR[4]=PR[2]+PR[3]", "PR[5]=PR[2]-PR[3]", "PR[6]=PR[3]-PR[2]",
        "PR[7]=PR[2]+PR[3]-PR[3]-PR[3]", "PR[8]=PR[2]");
    Rig c = run(p, cart(A, FLIP), cart(B, Config.DEFAULT));
    assertThat(elements(c.regs.position(4))).containsExactly(sum(A, B, 1));
    assertThat(elements(c.regs.position(5))).containsExactly(sum(A, B, -1));
    assertThat(elements(c.regs.position(6))).containsExactly(sum(B, A, -1));
    assertThat(elements(c.regs.position(7))).containsExactly(sum(A, B, -1));
    // the first term's CONFIG is kept
    assertThat(((Position.Cartesian) c.regs.position(4)).config()).isEqualTo(FLIP);
    assertThat(((Position.Cartesian) c.regs.position(6)).config()).isEqualTo(Config.DEFAULT);
    assertThat(((Position.Cartesian) c.regs.position(7)).config()).isEqualTo(FLIP);
    assertThat(c.regs.position(8)).isEqualTo(cart(A, FLIP));

    Rig j = run(p, joint(A), joint(B));
    assertThat(j.regs.position(4)).isEqualTo(joint(sum(A, B, 1)));
    assertThat(j.regs.position(5)).isEqualTo(joint(sum(A, B, -1)));
    assertThat(j.regs.position(6)).isEqualTo(joint(sum(B, A, -1)));
    assertThat(j.regs.position(7)).isEqualTo(joint(sum(A, B, -1)));
  }

  @Test
  void thePendantsTwoTermFormAddsAndSubtractsTheSame() {
    // PR[i]=PR[j]+PR[k] as the pendant builds it (Instruction.PosArithmetic)
    Program p = Tp.prog("PA",
        new Instruction.AssignPosReg(Item.of(4), new Instruction.PosArithmetic(Item.of(2), true, Item.of(3))),
        new Instruction.AssignPosReg(Item.of(5), new Instruction.PosArithmetic(Item.of(2), false, Item.of(3))));
    Rig c = run(p, cart(A, FLIP), cart(B, Config.DEFAULT));
    assertThat(elements(c.regs.position(4))).containsExactly(sum(A, B, 1));
    assertThat(elements(c.regs.position(5))).containsExactly(sum(A, B, -1));
    assertThat(((Position.Cartesian) c.regs.position(5)).config()).isEqualTo(FLIP);
    Rig j = run(p, joint(A), joint(B));
    assertThat(j.regs.position(4)).isEqualTo(joint(sum(A, B, 1)));
    assertThat(j.regs.position(5)).isEqualTo(joint(sum(A, B, -1)));
    Rig mixed = new Rig(p);
    mixed.regs.setPosition(2, joint(A));
    mixed.regs.setPosition(3, cart(B, Config.DEFAULT));
    assertThat(mixed.alarm(mixed.run()).code()).isEqualTo("INTP-205");
  }

  @Test
  void cartesianAndJointTogetherAreATypeMismatch() {
    for (String line : List.of("PR[4]=PR[2]+PR[3]", "PR[4]=PR[3]-PR[2]", "PR[4]=PR[2]+PR[2]-PR[3]", "PR[4]=PR[3]+PR[3]-PR[2]")) {
      Rig rig = new Rig(RunSemanticsTableTest.parse(line));
      rig.regs.setPosition(2, cart(A, Config.DEFAULT));
      rig.regs.setPosition(3, joint(B));
      Alarm a = rig.alarm(rig.run());
      assertThat(a.code()).as(line).isEqualTo("INTP-205");
    }
  }

  @Test
  void sumsWithTheCurrentPositionAndLocalPositions() {
    // PR[i]=LPOS-LPOS is the controller's idiom to clear a PR: a Cartesian PR of zeros.
    Program p = RunSemanticsTableTest.parse("PR[4]=LPOS-LPOS", "PR[5]=PR[2]+LPOS", "PR[6]=JPOS-JPOS", "PR[7]=JPOS+PR[3]",
        "PR[8]=LPOS", "PR[9]=JPOS");
    Rig rig = run(p, cart(A, FLIP), joint(B));
    Position.Cartesian lpos = rig.port.currentLpos();
    Position.Joint jpos = rig.port.currentJpos();
    assertThat(elements(rig.regs.position(4))).containsExactly(0, 0, 0, 0, 0, 0);
    assertThat(rig.regs.position(4)).isInstanceOf(Position.Cartesian.class);
    assertThat(elements(rig.regs.position(5))).containsExactly(sum(A, elements(lpos), 1));
    assertThat(((Position.Cartesian) rig.regs.position(5)).config()).isEqualTo(FLIP);
    assertThat(rig.regs.position(6)).isEqualTo(Position.Joint.ZERO);
    assertThat(rig.regs.position(7)).isEqualTo(joint(sum(elements(jpos), B, 1)));
    assertThat(rig.regs.position(8)).isEqualTo(lpos);
    assertThat(rig.regs.position(9)).isEqualTo(jpos);

    // P[n] terms: P[1] is taught at x = 100 (Tp.pos)
    Program withP = Tp.progWithPositions("PS", 2,
        new Instruction.AssignPosReg(Item.of(4), new Instruction.PosSum(new Instruction.FromLocal(1, ""),
            List.of(new Instruction.PosTerm(true, new Instruction.FromPosReg(Item.of(2))),
                new Instruction.PosTerm(false, new Instruction.FromLocal(2, ""))))),
        new Instruction.AssignPosReg(Item.of(5), new Instruction.FromLocal(2, "")));
    Rig r2 = run(withP, cart(A, FLIP), joint(B));
    double[] p1 = elements(Tp.pos(1).position());
    double[] p2 = elements(Tp.pos(2).position());
    assertThat(elements(r2.regs.position(4))).containsExactly(sum(sum(p1, A, 1), p2, -1));
    assertThat(((Position.Cartesian) r2.regs.position(4)).config()).isEqualTo(Config.DEFAULT);
    assertThat(r2.regs.position(5)).isEqualTo(Tp.pos(2).position());
  }

  @Test
  void everyElementReadsAndWritesItsOwnAxis() {
    for (Position start : new Position[] {cart(A, FLIP), joint(A)}) {
      for (int j = 1; j <= 6; j++) {
        Rig rig = new Rig(RunSemanticsTableTest.parse("R[1]=PR[2," + j + "]", "PR[2," + j + "]=PR[2," + j + "]+1000",
            "R[2]=PR[2," + j + "]", "PR[3," + j + "]=R[5]"));
        rig.regs.setPosition(2, start);
        rig.regs.setPosition(3, start);
        rig.regs.setInteger(5, 7);
        assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
        assertThat(rig.regs.number(1)).as("PR[2,%d] of %s", j, start).isEqualTo(A[j - 1]);
        assertThat(rig.regs.isInteger(1)).as("a PR element reads as a real").isFalse();
        assertThat(rig.regs.number(2)).isEqualTo(A[j - 1] + 1000);
        double[] expected = A.clone();
        expected[j - 1] += 1000;
        assertThat(elements(rig.regs.position(2))).containsExactly(expected);
        double[] seven = A.clone();
        seven[j - 1] = 7;
        assertThat(elements(rig.regs.position(3))).containsExactly(seven);
        assertThat(rig.regs.position(2).getClass()).isEqualTo(start.getClass());
        if (start instanceof Position.Cartesian) {
          assertThat(((Position.Cartesian) rig.regs.position(2)).config()).isEqualTo(FLIP);
        }
      }
    }
  }

  @Test
  void framesAreCopiedThroughPositionRegisters() {
    Rig rig = new Rig(RunSemanticsTableTest.parse("UFRAME[3]=PR[2]", "UTOOL[4]=PR[2]", "PR[5]=UFRAME[3]", "PR[6]=UTOOL[4]",
        "PR[7]=UFRAME[1]"));
    rig.regs.setPosition(2, cart(A, Config.DEFAULT));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.port.frame(Instruction.FrameKind.USER, 3)).isEqualTo(cart(A, Config.DEFAULT));
    assertThat(rig.port.frame(Instruction.FrameKind.TOOL, 4)).isEqualTo(cart(A, Config.DEFAULT));
    assertThat(rig.regs.position(5)).isEqualTo(cart(A, Config.DEFAULT));
    assertThat(rig.regs.position(6)).isEqualTo(cart(A, Config.DEFAULT));
    assertThat(rig.regs.position(7)).isEqualTo(rig.port.frame(Instruction.FrameKind.USER, 1));
  }
}
