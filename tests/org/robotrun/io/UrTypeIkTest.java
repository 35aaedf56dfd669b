package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.math.Transform;
import org.robotrun.robot.Config;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.RobotModel;
import org.robotrun.robot.UrTypeIk;

/**
 * The closed form for three parallel axes with an offset wrist ({@link UrTypeIk}) on UR-layout
 * URDFs: the importer test's UR5-like package (ROS 1 ur_description style, origins turned) and
 * DH-style files written here from Universal Robots' published DH tables (UR3, UR10e), one of
 * them mounted on a wall. Checks: the family is detected, 2000 targets round trip in their
 * CONFIG inside the limits, all eight solutions with eight different flag triples, a linear
 * move that never changes CONFIG, the wrist singularity, and no detection where J5 and J6 miss.
 */
class UrTypeIkTest {
  @TempDir
  Path tmp;

  /** UR DH tables (m): d1, a2, a3, d4, d5, d6 (Universal Robots, "DH parameters for calculations of kinematics"). */
  static final Map<String, double[]> DH = Map.of(
      "ur3", new double[] {0.1519, -0.24365, -0.21325, 0.11235, 0.08535, 0.0819},
      "ur10e", new double[] {0.1807, -0.6127, -0.57155, 0.17415, 0.11985, 0.11655});

  /** A DH-style URDF: joint k+1's origin is Tz(d_k)·Tx(a_k)·Rx(α_k), every axis z; tool0 as ur_description turns it. */
  static String dhUrdf(String name, double[] d, boolean wall, double elbowLimit) {
    double[] a = {0, d[1], d[2], 0, 0, 0};
    double[] dd = {d[0], 0, 0, d[3], d[4], d[5]};
    double[] al = {Math.PI / 2, 0, 0, Math.PI / 2, -Math.PI / 2, 0};
    String[] links = {"base_link", "shoulder_link", "upper_arm_link", "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link"};
    StringBuilder s = new StringBuilder("<?xml version=\"1.0\"?>\n<robot name=\"" + name + "\">\n");
    for (String l : links) {
      s.append("  <link name=\"").append(l).append("\"/>\n");
    }
    s.append("  <link name=\"flange\"/>\n  <link name=\"tool0\"/>\n");
    if (wall) {
      s.append("  <link name=\"world\"/>\n  <joint name=\"world-base\" type=\"fixed\"><parent link=\"world\"/><child link=\"base_link\"/>"
          + "<origin xyz=\"0.2 0 1.0\" rpy=\"0 1.5707963267948966 0\"/></joint>\n");
    }
    String[] names = {"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"};
    for (int i = 0; i < 6; i++) {
      String xyz = i == 0 ? "0 0 0" : a[i - 1] + " 0 " + dd[i - 1];
      String rpy = i == 0 ? "0 0 0" : al[i - 1] + " 0 0";
      double lim = i == 2 ? elbowLimit : 2 * Math.PI;
      s.append("  <joint name=\"").append(names[i]).append("\" type=\"revolute\"><parent link=\"").append(links[i])
          .append("\"/><child link=\"").append(links[i + 1]).append("\"/><origin xyz=\"").append(xyz).append("\" rpy=\"").append(rpy)
          .append("\"/><axis xyz=\"0 0 1\"/><limit lower=\"").append(-lim).append("\" upper=\"").append(lim)
          .append("\" effort=\"150\" velocity=\"3.14\"/></joint>\n");
    }
    s.append("  <joint name=\"wrist_3-flange\" type=\"fixed\"><parent link=\"wrist_3_link\"/><child link=\"flange\"/><origin xyz=\"0 0 ")
        .append(dd[5]).append("\" rpy=\"0 -1.5707963267948966 -1.5707963267948966\"/></joint>\n");
    s.append("  <joint name=\"flange-tool0\" type=\"fixed\"><parent link=\"flange\"/><child link=\"tool0\"/>"
        + "<origin xyz=\"0 0 0\" rpy=\"1.5707963267948966 0 1.5707963267948966\"/></joint>\n");
    return s.append("</robot>\n").toString();
  }

  private RobotModel arm(String which) throws Exception {
    if (which.equals("ur5-like")) {
      return UrdfImporter.importRobot(TestArms.offsetPackage(tmp), Map.of()).model();
    }
    Path f = tmp.resolve(which + ".urdf");
    String id = which.replace("-wall", "");
    TestArms.write(f, dhUrdf(which, DH.get(id), which.endsWith("-wall"), id.equals("ur10e") ? Math.PI : 2 * Math.PI));
    return UrdfImporter.importRobot(f, Map.of()).model();
  }

  @ParameterizedTest
  @ValueSource(strings = {"ur5-like", "ur3", "ur10e", "ur3-wall"})
  void urLayoutsGetTheClosedFormAndRoundTripInTheirConfig(String which) throws Exception {
    RobotModel m = arm(which);
    IkSolver solver = IkSolver.forModel(m);
    assertThat(solver.kind()).isEqualTo(UrTypeIk.KIND);
    assertThat(m.wristKind()).isEqualTo("parallel");
    RosIndustrialLayoutTest.roundTrip(m, solver, 2000, 31 + which.length());
  }

  @Test
  void anglesRoundedToFourDecimalsStillGetTheClosedForm() throws Exception {
    // rpy="1.5708 0 0" as hand-written files give it: axes 4e-6 rad off parallel.
    Path f = tmp.resolve("rounded.urdf");
    TestArms.write(f, dhUrdf("rounded", DH.get("ur10e"), false, Math.PI).replace("1.5707963267948966", "1.5708"));
    RobotModel m = UrdfImporter.importRobot(f, Map.of()).model();
    IkSolver solver = IkSolver.forModel(m);
    assertThat(solver.kind()).isEqualTo(UrTypeIk.KIND);
    RosIndustrialLayoutTest.roundTrip(m, solver, 500, 11);
  }

  @Test
  void eightSolutionsWithEightDifferentFlagTriples() throws Exception {
    RobotModel m = arm("ur10e");
    UrTypeIk ik = new UrTypeIk(m);
    Random rnd = new Random(7);
    int checked = 0;
    for (int k = 0; k < 200; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = (rnd.nextDouble() - 0.5) * 2 * Math.PI;
      }
      Transform x = ForwardKinematics.flangePoseInBase(m, q);
      List<double[]> all = ik.baseSolutions(x);
      if (all.size() < 8) {
        continue;
      }
      assertThat(all).hasSize(8);
      Set<String> flags = new HashSet<>();
      for (double[] s : all) {
        Transform y = ForwardKinematics.flangePoseInBase(m, s);
        assertThat(y.distanceTo(x)).isLessThan(1e-6);
        assertThat(y.rotationAngleTo(x)).isLessThan(1e-9);
        Config c = ik.configOf(s);
        flags.add(c.flip() + " " + c.up() + " " + c.top());
      }
      assertThat(flags).as("target %d", k).hasSize(8);
      checked++;
    }
    assertThat(checked).isGreaterThan(100);
  }

  @Test
  void aLinearMoveKeepsItsConfigAndMovesTheJointsSmoothly() throws Exception {
    RobotModel m = arm("ur5-like");
    IkSolver ik = IkSolver.forModel(m);
    double[] q = {0.4, -1.2, 1.5, -1.8, -1.4, 0.3};
    Config start = ik.configOf(q);
    Transform x0 = ForwardKinematics.flangePoseInBase(m, q);
    for (int step = 1; step <= 300; step++) {
      // 1 mm steps along base -x then z, with a slow turn about the tool z (inside the reach).
      Transform x = Transform.translation(step <= 150 ? -step : -150, 0, step <= 150 ? 0 : step - 150).compose(x0)
          .compose(Transform.rotation(0, 0, 1, 0.001 * step));
      IkResult r = ik.solveNearest(x, q);
      assertThat(r).as("step %d", step).isInstanceOf(IkResult.Solved.class);
      double[] next = ((IkResult.Solved) r).q();
      for (int i = 0; i < 6; i++) {
        assertThat(Math.abs(next[i] - q[i])).as("step %d J%d", step, i + 1).isLessThan(0.05);
      }
      assertThat(ik.configOf(next)).as("step %d", step).isEqualTo(start);
      q = next;
    }
  }

  @Test
  void theWristSingularityStillSolvesKeepingJ6() throws Exception {
    RobotModel m = arm("ur3");
    IkSolver ik = IkSolver.forModel(m);
    // J5 = 0 lines J6 up with J2..J4: only J4 + J6 is defined.
    double[] q = {0.3, -1.0, 1.2, -0.5, 0.0, 0.7};
    Transform x = ForwardKinematics.flangePoseInBase(m, q);
    IkResult r = ik.solveNearest(x, q);
    double[] a = ((IkResult.Solved) r).q();
    Transform y = ForwardKinematics.flangePoseInBase(m, a);
    assertThat(y.distanceTo(x)).isLessThan(1e-6);
    assertThat(y.rotationAngleTo(x)).isLessThan(1e-8);
    assertThat(a[5]).isCloseTo(0.7, org.assertj.core.data.Offset.offset(1e-6));
  }

  @Test
  void j5AndJ6ThatDoNotMeetAreNotTakenForTheFamily() throws Exception {
    Path f = tmp.resolve("miss.urdf");
    // wrist_3's origin moved 20 mm off the J5 axis.
    String text = dhUrdf("miss", DH.get("ur3"), false, 2 * Math.PI).replace(
        "<origin xyz=\"0.0 0 0.08535\" rpy=\"-1.5707963267948966 0 0\"/>", "<origin xyz=\"0.02 0 0.08535\" rpy=\"-1.5707963267948966 0 0\"/>");
    assertThat(text).contains("0.02 0 0.08535");
    TestArms.write(f, text);
    RobotModel m = UrdfImporter.importRobot(f, Map.of()).model();
    assertThat(UrTypeIk.applies(m)).isFalse();
    assertThat(IkSolver.forModel(m).kind()).isNotEqualTo(UrTypeIk.KIND);
  }
}
