package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BiPredicate;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;

/**
 * Truth tables of the interpreter (issue 31): every comparison operator with its left side below,
 * at and above the right side, integer and real, against a register and against a constant, in
 * each form a program can test a condition (IF ...,JMP; IF (...) THEN/ELSE; a mixed-logic flag
 * assignment; WAIT with TIMEOUT), combined with AND, OR and NOT; and FOR loops at their bounds.
 * The expected answer is Java's own comparison of the two numbers, never a run's output.
 */
class ComparisonTruthTableTest {

  record Op(String tp, BiPredicate<Double, Double> truth) {}

  static final List<Op> OPS = List.of(
      new Op("=", (a, b) -> a.doubleValue() == b.doubleValue()),
      new Op("<>", (a, b) -> a.doubleValue() != b.doubleValue()),
      new Op("<", (a, b) -> a < b),
      new Op("<=", (a, b) -> a <= b),
      new Op(">", (a, b) -> a > b),
      new Op(">=", (a, b) -> a >= b));

  /** Right sides and, for each, a left side below, at and above it. */
  record Values(String kind, String right, double rightValue, String[] lefts, double[] leftValues) {}

  static final List<Values> VALUES = List.of(
      new Values("integer", "5", 5, new String[] {"4", "5", "6"}, new double[] {4, 5, 6}),
      new Values("negative integer", "(-3)", -3, new String[] {"(-4)", "(-3)", "(-2)"}, new double[] {-4, -3, -2}),
      new Values("real", "2.5", 2.5, new String[] {"2.25", "2.5", "2.75"}, new double[] {2.25, 2.5, 2.75}),
      new Values("real against integer", "3", 3, new String[] {"2.999", "3.0", "3.001"}, new double[] {2.999, 3, 3.001}));

  static Program parse(String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  TT\n/ATTR\nDEFAULT_GROUP\t= *,*,*,*,*;\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format("%4d:  %s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n/END\n");
    LsReadResult r = LsReader.parse("TT.LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics() + "\n" + sb).isFalse();
    return r.program();
  }

  static Rig run(String... lines) {
    Rig rig = new Rig(parse(lines));
    Outcome o = rig.run();
    assertThat(o).as(String.join("\n", lines)).isInstanceOf(Outcome.Finished.class);
    return rig;
  }

  @TestFactory
  Stream<DynamicTest> everyOperatorBelowAtAndAboveEqualityInEveryForm() {
    List<DynamicTest> tests = new ArrayList<>();
    for (Values v : VALUES) {
      for (int k = 0; k < 3; k++) {
        String left = v.lefts()[k];
        double a = v.leftValues()[k];
        String where = k == 0 ? "below" : k == 1 ? "at" : "above";
        for (Op op : OPS) {
          boolean expected = op.truth().test(a, v.rightValue());
          for (boolean againstRegister : new boolean[] {true, false}) {
            String rhs = againstRegister ? "R[2]" : v.right();
            String cond = "R[1]" + op.tp() + rhs;
            String name = v.kind() + " " + where + ": R[1]=" + left + " " + op.tp() + " " + (againstRegister ? "R[2]=" + v.right() : v.right())
                + " is " + expected;
            tests.add(DynamicTest.dynamicTest(name, () -> {
              Rig rig = run(
                  "R[1]=" + left,
                  "R[2]=" + v.right(),
                  "F[5]=ON",
                  "F[6]=OFF",
                  // classic IF, JMP
                  "IF " + cond + ",JMP LBL[1]",
                  "R[10]=0",
                  "JMP LBL[2]",
                  "LBL[1]",
                  "R[10]=1",
                  "LBL[2]",
                  // mixed logic into a flag, NOT, AND/OR with a known flag
                  "F[1]=(" + cond + ")",
                  "F[2]=(!(" + cond + "))",
                  "F[3]=(" + cond + " AND F[5])",
                  "F[4]=(" + cond + " OR F[6])",
                  "F[7]=(" + cond + " AND F[6])",
                  "F[8]=(" + cond + " OR F[5])",
                  // block IF
                  "IF (" + cond + ") THEN",
                  "R[11]=1",
                  "ELSE",
                  "R[11]=0",
                  "ENDIF",
                  // WAIT: a true condition passes at once, a false one times out to LBL[3]
                  "$WAITTMOUT=10",
                  "R[12]=1",
                  "WAIT " + cond + " TIMEOUT,LBL[3]",
                  "JMP LBL[4]",
                  "LBL[3]",
                  "R[12]=0",
                  "LBL[4]");
              assertThat(rig.regs.number(10)).as("IF ...,JMP").isEqualTo(expected ? 1 : 0);
              assertThat(rig.regs.bit(IoKind.F, 1)).as("F[1]=(cond)").isEqualTo(expected);
              assertThat(rig.regs.bit(IoKind.F, 2)).as("F[2]=(!(cond))").isEqualTo(!expected);
              assertThat(rig.regs.bit(IoKind.F, 3)).as("cond AND ON").isEqualTo(expected);
              assertThat(rig.regs.bit(IoKind.F, 4)).as("cond OR OFF").isEqualTo(expected);
              assertThat(rig.regs.bit(IoKind.F, 7)).as("cond AND OFF").isFalse();
              assertThat(rig.regs.bit(IoKind.F, 8)).as("cond OR ON").isTrue();
              assertThat(rig.regs.number(11)).as("IF (cond) THEN ... ELSE").isEqualTo(expected ? 1 : 0);
              assertThat(rig.regs.number(12)).as("WAIT cond TIMEOUT").isEqualTo(expected ? 1 : 0);
            }));
          }
        }
      }
    }
    return tests.stream();
  }

  @TestFactory
  Stream<DynamicTest> twoComparisonsJoinedByAndOrInAStandardIf() {
    // IF R[1]<op>5 AND R[2]<op>5,JMP / OR: the four combinations of two comparisons, each at its edge.
    List<DynamicTest> tests = new ArrayList<>();
    for (String join : new String[] {"AND", "OR"}) {
      for (Op op : OPS) {
        for (double a : new double[] {4, 5, 6}) {
          for (double b : new double[] {4, 5, 6}) {
            boolean p = op.truth().test(a, 5.0);
            boolean q = op.truth().test(b, 5.0);
            boolean expected = join.equals("AND") ? p && q : p || q;
            String name = "R[1]=" + (int) a + " " + op.tp() + " 5 " + join + " R[2]=" + (int) b + " " + op.tp() + " 5 is " + expected;
            tests.add(DynamicTest.dynamicTest(name, () -> {
              Rig rig = run("R[1]=" + (int) a, "R[2]=" + (int) b,
                  "IF R[1]" + op.tp() + "5 " + join + " R[2]" + op.tp() + "5,JMP LBL[1]",
                  "R[10]=0", "JMP LBL[2]", "LBL[1]", "R[10]=1", "LBL[2]");
              assertThat(rig.regs.number(10)).isEqualTo(expected ? 1 : 0);
            }));
          }
        }
      }
    }
    return tests.stream();
  }

  @TestFactory
  Stream<DynamicTest> selectMatchesOnlyTheEqualCase() {
    List<DynamicTest> tests = new ArrayList<>();
    for (int v : new int[] {1, 2, 3, 4}) {
      tests.add(DynamicTest.dynamicTest("SELECT R[1]=" + v, () -> {
        Rig rig = run("R[1]=" + v, "SELECT R[1]=2,JMP LBL[2]", "       =3,JMP LBL[3]", "       ELSE,JMP LBL[9]",
            "LBL[2]", "R[10]=2", "JMP LBL[10]", "LBL[3]", "R[10]=3", "JMP LBL[10]", "LBL[9]", "R[10]=9", "LBL[10]");
        assertThat(rig.regs.number(10)).isEqualTo(v == 2 || v == 3 ? v : 9);
      }));
    }
    return tests.stream();
  }

  /** Runs FOR R[1]=from TO|DOWNTO to, counting passes in R[2] and summing R[1] in R[3]. */
  static Rig forLoop(int from, String dir, int to) {
    // A FOR bound is an integer constant, R[i] or AR[i]: negative bounds go through R[5] and R[6].
    String a = from < 0 ? "R[5]" : String.valueOf(from);
    String b = to < 0 ? "R[6]" : String.valueOf(to);
    return run("R[5]=" + from, "R[6]=" + to, "R[2]=0", "R[3]=0", "FOR R[1]=" + a + " " + dir + " " + b, "R[2]=R[2]+1",
        "R[3]=R[3]+R[1]", "ENDFOR");
  }

  @Test
  void forLoopsRunOncePerValueFromTheFirstBoundToTheLastInclusive() {
    record Case(int from, String dir, int to) {}
    for (Case c : List.of(new Case(1, "TO", 1), new Case(1, "TO", 3), new Case(3, "DOWNTO", 1), new Case(2, "DOWNTO", 2),
        new Case(1, "TO", 0), new Case(0, "DOWNTO", 1), new Case(-2, "TO", 2), new Case(2, "DOWNTO", -2))) {
      int passes = 0;
      int sum = 0;
      int step = c.dir().equals("TO") ? 1 : -1;
      for (int i = c.from(); step > 0 ? i <= c.to() : i >= c.to(); i += step) {
        passes++;
        sum += i;
      }
      Rig rig = forLoop(c.from(), c.dir(), c.to());
      assertThat(rig.regs.number(2)).as("passes of FOR %d %s %d", c.from(), c.dir(), c.to()).isEqualTo(passes);
      assertThat(rig.regs.number(3)).as("sum of FOR %d %s %d", c.from(), c.dir(), c.to()).isEqualTo(sum);
      if (passes > 0) {
        // docs/tp-execution.md: after a completed loop the counter holds the end value
        assertThat(rig.regs.number(1)).as("counter after FOR %d %s %d", c.from(), c.dir(), c.to()).isEqualTo(c.to());
      }
    }
  }

  @Test
  void forLoopBoundsFromRegistersAreReadOnce() {
    // R[4]=3 as the bound; the body lowers R[4], the loop still runs three times (the bound was read at FOR).
    Rig rig = run("R[2]=0", "R[4]=3", "FOR R[1]=1 TO R[4]", "R[2]=R[2]+1", "R[4]=1", "ENDFOR");
    assertThat(rig.regs.number(2)).isEqualTo(3);
  }
}
