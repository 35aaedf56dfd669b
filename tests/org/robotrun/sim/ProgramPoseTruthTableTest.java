package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * Program to pose (issue 31): a program in a rotated user frame and a rotated tool frame, with
 * {@code Offset,PR[]}, {@code Tool_Offset,PR[]}, {@code INC} and PR arithmetic whose offsets carry
 * W, P and R. After each motion the TCP is compared with a pose composed here, with this test's
 * own 4×4 arithmetic and FANUC's W, P, R convention (R = Rz(r)·Ry(p)·Rx(w), fixed axes), from the
 * rules docs/motion.md and docs/tp-execution.md state:
 *
 * <ul>
 *   <li>a Cartesian P[] is the TCP pose in its user frame: X_WT = UFRAME · P;
 *   <li>{@code Offset,PR[i]} adds the PR's X, Y, Z, W, P, R to the target's values in its user
 *       frame;
 *   <li>{@code Tool_Offset,PR[i]} moves the target by the PR as a transform in its tool frame:
 *       X_WT = UFRAME · P · PR;
 *   <li>{@code INC} adds the target to the current position (LPOS in the user frame);
 *   <li>{@code PR[k]=PR[i]+PR[j]} adds element by element.
 * </ul>
 */
class ProgramPoseTruthTableTest {
  /** UFRAME[2]: moved and turned about all three axes (X, Y, Z mm; W, P, R deg). */
  static final double[] UF2 = {420, -60, 30, 8, -12, 35};
  /** UTOOL[2]: a tool 120 mm out, off-axis, tilted 20° and turned 45°. */
  static final double[] UT2 = {15, -10, 120, 0, 20, 45};
  /** P[1] in UF2/UT2. */
  static final double[] P1 = {-20, 30, 60, 180, 10, -25};
  /** PR[1] (Offset): every element non-zero. */
  static final double[] PR1 = {12, -18, 25, 6, -9, 14};
  /** PR[2] (Tool_Offset): every element non-zero. */
  static final double[] PR2 = {8, 14, -30, -7, 11, 20};
  /** P[2] (INC). */
  static final double[] P2 = {-15, 10, 5, 4, -3, 9};

  // ---- this test's own pose arithmetic: 4x4 row-major, mm and degrees in, FANUC W, P, R ----

  static double[] pose(double[] xyzwpr) {
    double w = Math.toRadians(xyzwpr[3]);
    double p = Math.toRadians(xyzwpr[4]);
    double r = Math.toRadians(xyzwpr[5]);
    double[] rx = {1, 0, 0, 0, Math.cos(w), -Math.sin(w), 0, Math.sin(w), Math.cos(w)};
    double[] ry = {Math.cos(p), 0, Math.sin(p), 0, 1, 0, -Math.sin(p), 0, Math.cos(p)};
    double[] rz = {Math.cos(r), -Math.sin(r), 0, Math.sin(r), Math.cos(r), 0, 0, 0, 1};
    double[] rot = mul3(rz, mul3(ry, rx));
    return new double[] {rot[0], rot[1], rot[2], xyzwpr[0], rot[3], rot[4], rot[5], xyzwpr[1], rot[6], rot[7], rot[8],
        xyzwpr[2], 0, 0, 0, 1};
  }

  static double[] mul3(double[] a, double[] b) {
    double[] c = new double[9];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        for (int k = 0; k < 3; k++) {
          c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
        }
      }
    }
    return c;
  }

  static double[] mul(double[] a, double[] b) {
    double[] c = new double[16];
    for (int i = 0; i < 4; i++) {
      for (int j = 0; j < 4; j++) {
        for (int k = 0; k < 4; k++) {
          c[4 * i + j] += a[4 * i + k] * b[4 * k + j];
        }
      }
    }
    return c;
  }

  static double[] inverse(double[] m) {
    // rigid: R^T, -R^T t
    double[] r = new double[16];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        r[4 * i + j] = m[4 * j + i];
      }
    }
    for (int i = 0; i < 3; i++) {
      r[4 * i + 3] = -(r[4 * i] * m[3] + r[4 * i + 1] * m[7] + r[4 * i + 2] * m[11]);
    }
    r[15] = 1;
    return r;
  }

  static double[] add(double[] a, double[] b) {
    double[] c = new double[6];
    for (int i = 0; i < 6; i++) {
      c[i] = a[i] + b[i];
    }
    return c;
  }

  /** Position error (mm) and rotation error (deg) between two poses. */
  static void assertSamePose(String what, double[] actual, double[] expected) {
    double dp = Math.sqrt(sq(actual[3] - expected[3]) + sq(actual[7] - expected[7]) + sq(actual[11] - expected[11]));
    // angle of R_a^T R_e from its trace
    double tr = 0;
    for (int i = 0; i < 3; i++) {
      for (int k = 0; k < 3; k++) {
        tr += actual[4 * k + i] * expected[4 * k + i];
      }
    }
    double angle = Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, (tr - 1) / 2))));
    assertThat(dp).as(what + ": TCP position off by (mm)").isLessThan(0.01);
    assertThat(angle).as(what + ": TCP orientation off by (deg)").isLessThan(0.01);
  }

  static double sq(double v) {
    return v * v;
  }

  static double[] actualTcp(Controller c) {
    Xyzwpr t = c.tcpInWorld();
    return pose(new double[] {t.x(), t.y(), t.z(), t.wDeg(), t.pDeg(), t.rDeg()});
  }

  // ---- the program ----

  static String pos(int n, int uf, int ut, double[] v) {
    return String.format(java.util.Locale.ROOT, """
        P[%d]{
           GP1:
        	UF : %d, UT : %d,		CONFIG : 'N U T, 0, 0, 0',
        	X = %9.3f  mm,	Y = %9.3f  mm,	Z = %9.3f  mm,
        	W = %9.3f deg,	P = %9.3f deg,	R = %9.3f deg
        };
        """, n, uf, ut, v[0], v[1], v[2], v[3], v[4], v[5]);
  }

  static List<String> setPr(int pr, double[] v) {
    List<String> lines = new ArrayList<>();
    for (int j = 0; j < 6; j++) {
      lines.add(String.format(java.util.Locale.ROOT, "PR[%d,%d]=%s", pr, j + 1, v[j] < 0 ? "(" + v[j] + ")" : String.valueOf(v[j])));
    }
    return lines;
  }

  static Program program(List<String> lines) {
    StringBuilder sb = new StringBuilder("/PROG  POSE\n/ATTR\n/MN\n");
    for (int i = 0; i < lines.size(); i++) {
      sb.append(String.format("%4d:  %s ;%n", i + 1, lines.get(i)));
    }
    sb.append("/POS\n").append(pos(1, 2, 2, P1)).append(pos(2, 2, 2, P2)).append("/END\n");
    LsReadResult r = LsReader.parse("POSE.LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics() + "\n" + sb).isFalse();
    return r.program();
  }

  @Test
  void offsetToolOffsetIncAndPrArithmeticInRotatedFramesLandWhereTheComposedPoseSays() {
    List<String> lines = new ArrayList<>();
    lines.add("PR[9]=LPOS"); // makes PR[9] Cartesian
    for (int pr : new int[] {1, 2, 5, 6}) {
      lines.add("PR[" + pr + "]=PR[9]");
    }
    lines.addAll(setPr(5, UF2));
    lines.addAll(setPr(6, UT2));
    lines.addAll(setPr(1, PR1));
    lines.addAll(setPr(2, PR2));
    lines.add("UFRAME[2]=PR[5]");
    lines.add("UTOOL[2]=PR[6]");
    lines.add("UFRAME_NUM=2");
    lines.add("UTOOL_NUM=2");
    lines.add("J P[1] 100% FINE");
    lines.add("PAUSE"); // 1: P[1]
    lines.add("L P[1] 200mm/sec FINE Offset,PR[1]");
    lines.add("PAUSE"); // 2: P[1] + PR[1], element by element, in UF2
    lines.add("L P[1] 200mm/sec FINE Tool_Offset,PR[2]");
    lines.add("PAUSE"); // 3: P[1] then PR[2] in the tool frame
    lines.add("L P[2] 200mm/sec FINE INC");
    lines.add("PAUSE"); // 4: (LPOS after 3) + P[2]
    lines.add("PR[3]=PR[1]+PR[2]");
    lines.add("PR[4]=PR[1]-PR[2]");
    lines.add("L P[1] 200mm/sec FINE Offset,PR[3]");
    lines.add("PAUSE"); // 5: P[1] + (PR[1] + PR[2])
    lines.add("J P[1] 50% FINE Offset,PR[4]");
    lines.add("PAUSE"); // 6: a J move with a Cartesian offset, P[1] + (PR[1] - PR[2])
    lines.add("PR[7]=P[1]");
    lines.add("L PR[7] 200mm/sec FINE Tool_Offset,PR[1]");
    lines.add("PAUSE"); // 7: a PR target (copied from P[1]) with a tool offset
    lines.add("R[1]=1");
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(program(lines));
    c.run("POSE", 1, true);
    List<double[]> atPauses = new ArrayList<>();
    for (int i = 0; i < 100_000 && (c.busy() || atPauses.isEmpty()) && atPauses.size() <= 7; i++) {
      sim.step();
      if (c.status().state() == ExecutionStatus.State.PAUSED) {
        atPauses.add(actualTcp(c));
        c.run("POSE", c.status().line(), true);
      }
    }
    assertThat(c.activeAlarms()).as("alarms").isEmpty();
    assertThat(atPauses).hasSize(7);
    assertThat(c.registers().number(1)).as("ran to its end").isEqualTo(1);

    double[] uf = pose(UF2);
    double[] p1 = pose(P1);
    assertSamePose("P[1] in UF2", atPauses.get(0), mul(uf, p1));
    assertSamePose("Offset,PR[1]", atPauses.get(1), mul(uf, pose(add(P1, PR1))));
    double[] afterToolOffset = mul(uf, mul(p1, pose(PR2)));
    assertSamePose("Tool_Offset,PR[2]", atPauses.get(2), afterToolOffset);
    // INC: LPOS (the TCP in UF2, as X, Y, Z, W, P, R) plus P[2] element by element.
    double[] lpos = xyzwprOf(mul(inverse(uf), afterToolOffset));
    assertSamePose("INC P[2]", atPauses.get(3), mul(uf, pose(add(lpos, P2))));
    double[] pr3 = add(PR1, PR2);
    assertSamePose("Offset,PR[3]=PR[1]+PR[2]", atPauses.get(4), mul(uf, pose(add(P1, pr3))));
    double[] pr4 = new double[6];
    for (int j = 0; j < 6; j++) {
      pr4[j] = PR1[j] - PR2[j];
    }
    assertSamePose("J with Offset,PR[4]=PR[1]-PR[2]", atPauses.get(5), mul(uf, pose(add(P1, pr4))));
    assertSamePose("PR[7]=P[1] with Tool_Offset,PR[1]", atPauses.get(6), mul(uf, mul(p1, pose(PR1))));

    // PR arithmetic element by element, W, P, R included.
    Position.Cartesian r3 = (Position.Cartesian) c.registers().position(3);
    Position.Cartesian r4 = (Position.Cartesian) c.registers().position(4);
    for (int j = 0; j < 6; j++) {
      assertThat(r3.element(j + 1)).as("PR[3,%d]", j + 1).isCloseTo(pr3[j], offset(1e-9));
      assertThat(r4.element(j + 1)).as("PR[4,%d]", j + 1).isCloseTo(pr4[j], offset(1e-9));
    }
  }

  /** X, Y, Z, W, P, R (deg) of a pose, FANUC convention (P in [-90, 90]). */
  static double[] xyzwprOf(double[] m) {
    double p = Math.asin(-m[8]);
    double w = Math.atan2(m[9], m[10]);
    double r = Math.atan2(m[4], m[0]);
    return new double[] {m[3], m[7], m[11], Math.toDegrees(w), Math.toDegrees(p), Math.toDegrees(r)};
  }
}
