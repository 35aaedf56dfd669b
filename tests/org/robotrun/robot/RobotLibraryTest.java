package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * Every shipped model against the chain facts of shared/robots/chains (copied as numbers into
 * tests/resources/robots/chain-facts.json): an independent FK written here from those numbers
 * (4x4 matrices, URDF convention: origin xyz, rpy, then a rotation about the axis), the closed
 * form's parameters derived at load against the published ones, limits and speeds, and an IK
 * round trip with CONFIG on 2000 random in-limit joint vectors per model.
 */
class RobotLibraryTest {
  static final JsonNode FACTS = readFacts();

  static Stream<String> models() {
    return RobotDefinitions.LIBRARY.stream();
  }

  private static JsonNode readFacts() {
    try (InputStream in = RobotLibraryTest.class.getResourceAsStream("/robots/chain-facts.json")) {
      return new ObjectMapper().readTree(in).get("models");
    } catch (Exception e) {
      throw new IllegalStateException(e);
    }
  }

  // ---- the independent FK ------------------------------------------------------------------

  static double[][] mul(double[][] a, double[][] b) {
    double[][] c = new double[4][4];
    for (int i = 0; i < 4; i++) {
      for (int j = 0; j < 4; j++) {
        for (int k = 0; k < 4; k++) {
          c[i][j] += a[i][k] * b[k][j];
        }
      }
    }
    return c;
  }

  static double[][] origin(JsonNode xyz, JsonNode rpyDeg) {
    double r = Math.toRadians(rpyDeg.get(0).asDouble()), p = Math.toRadians(rpyDeg.get(1).asDouble());
    double y = Math.toRadians(rpyDeg.get(2).asDouble());
    double cr = Math.cos(r), sr = Math.sin(r), cp = Math.cos(p), sp = Math.sin(p), cy = Math.cos(y), sy = Math.sin(y);
    return new double[][] {
      {cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr, xyz.get(0).asDouble()},
      {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr, xyz.get(1).asDouble()},
      {-sp, cp * sr, cp * cr, xyz.get(2).asDouble()},
      {0, 0, 0, 1}};
  }

  static double[][] axisAngle(JsonNode axis, double t) {
    double x = axis.get(0).asDouble(), y = axis.get(1).asDouble(), z = axis.get(2).asDouble();
    double n = Math.sqrt(x * x + y * y + z * z);
    x /= n;
    y /= n;
    z /= n;
    double c = Math.cos(t), s = Math.sin(t), v = 1 - c;
    return new double[][] {
      {c + x * x * v, x * y * v - z * s, x * z * v + y * s, 0},
      {y * x * v + z * s, c + y * y * v, y * z * v - x * s, 0},
      {z * x * v - y * s, z * y * v + x * s, c + z * z * v, 0},
      {0, 0, 0, 1}};
  }

  /** Flange pose in base_link (mm) from the chain facts, q in rad (URDF convention). */
  static double[][] factsFk(JsonNode m, double[] q) {
    double[][] t = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    for (int i = 0; i < 6; i++) {
      JsonNode j = m.get("joints").get(i);
      t = mul(mul(t, origin(j.get("xyz"), j.get("rpy"))), axisAngle(j.get("axis"), q[i]));
    }
    return mul(t, origin(m.get("flange").get("xyz"), m.get("flange").get("rpy")));
  }

  static void assertSamePose(Transform X, double[][] T, String what) {
    assertThat(Math.hypot(Math.hypot(X.x() - T[0][3], X.y() - T[1][3]), X.z() - T[2][3])).as(what + " position (mm)").isLessThan(1e-9);
    double[][] r = {{X.r00(), X.r01(), X.r02()}, {X.r10(), X.r11(), X.r12()}, {X.r20(), X.r21(), X.r22()}};
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        assertThat(Math.abs(r[i][j] - T[i][j])).as(what + " rotation r%d%d", i, j).isLessThan(1e-12);
      }
    }
  }

  /** Random joint vectors inside both the model's and the facts' limits. */
  static List<double[]> randomJoints(RobotModel model, JsonNode m, int count, long seed) {
    Random rnd = new Random(seed);
    List<double[]> out = new ArrayList<>();
    for (int k = 0; k < count; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        JsonNode j = m.get("joints").get(i);
        double lo = Math.max(model.joint(i).lowerRad(), Math.toRadians(j.get("lower").asDouble()));
        double hi = Math.min(model.joint(i).upperRad(), Math.toRadians(j.get("upper").asDouble()));
        q[i] = lo + rnd.nextDouble() * (hi - lo);
      }
      out.add(q);
    }
    return out;
  }

  // ---- tests ---------------------------------------------------------------------------------

  @ParameterizedTest
  @MethodSource("models")
  void forwardKinematicsAtZeroAndAtRandomJointsMatchesTheChainFacts(String id) {
    RobotModel model = RobotDefinitions.load(id);
    JsonNode m = FACTS.get(id);
    Transform home = ForwardKinematics.flangePoseInBase(model, new double[6]);
    assertSamePose(home, factsFk(m, new double[6]), id + " at q = 0");
    JsonNode h = m.get("homeFlangeInBase");
    assertThat(home.x()).isCloseTo(h.get(0).asDouble(), org.assertj.core.api.Assertions.within(1e-9));
    assertThat(home.y()).isCloseTo(h.get(1).asDouble(), org.assertj.core.api.Assertions.within(1e-9));
    assertThat(home.z()).isCloseTo(h.get(2).asDouble(), org.assertj.core.api.Assertions.within(1e-9));
    assertThat(model.X_WB().z()).isEqualTo(-m.get("worldZ").asDouble());
    for (double[] q : randomJoints(model, m, 500, id.hashCode())) {
      assertSamePose(ForwardKinematics.flangePoseInBase(model, q), factsFk(m, q), id);
    }
  }

  @ParameterizedTest
  @MethodSource("models")
  void limitsSpeedsAndCouplingAreTheSources(String id) {
    RobotModel model = RobotDefinitions.load(id);
    JsonNode m = FACTS.get(id);
    for (int i = 0; i < 6; i++) {
      JsonNode j = m.get("joints").get(i);
      assertThat(model.joint(i).name()).isEqualTo("J" + (i + 1));
      assertThat(Math.toDegrees(model.joint(i).maxSpeedRadPerSec())).as("%s J%d speed", id, i + 1)
          .isCloseTo(j.get("maxVelocity").asDouble(), org.assertj.core.api.Assertions.within(1e-3));
      if (id.equals("lrmate200id") && i == 0) {
        // Today's file keeps ROS-I's ±170° (the reference targets use it); FANUC-CORP says ±180°.
        assertThat(Math.toDegrees(model.joint(0).upperRad())).isCloseTo(170, org.assertj.core.api.Assertions.within(1e-9));
        continue;
      }
      assertThat(Math.toDegrees(model.joint(i).lowerRad())).as("%s J%d lower", id, i + 1)
          .isCloseTo(j.get("lower").asDouble(), org.assertj.core.api.Assertions.within(1e-3));
      assertThat(Math.toDegrees(model.joint(i).upperRad())).as("%s J%d upper", id, i + 1)
          .isCloseTo(j.get("upper").asDouble(), org.assertj.core.api.Assertions.within(1e-3));
    }
    assertThat(model.coupledJ3()).isEqualTo(m.get("coupledJ3").asBoolean());
  }

  @ParameterizedTest
  @MethodSource("models")
  void theClosedFormIsDerivedFromTheChainWhereThePublishedParametersSayOpw(String id) {
    RobotModel model = RobotDefinitions.load(id);
    JsonNode o = FACTS.get(id).get("opw");
    IkSolver solver = IkSolver.forModel(model);
    if (o.isNull()) {
      assertThat(model.opw()).isEmpty();
      assertThat(solver.kind()).isEqualTo(OffsetWristIk.KIND);
      assertThat(model.wristKind()).isEqualTo("offset");
      return;
    }
    assertThat(solver.kind()).isEqualTo(ClosedFormIk.KIND);
    OpwParameters p = model.opw().orElseThrow();
    org.assertj.core.data.Offset<Double> mm = org.assertj.core.api.Assertions.within(1e-9);
    assertThat(p.a1()).isCloseTo(o.get("a1").asDouble(), mm);
    assertThat(p.a2()).isCloseTo(o.get("a2").asDouble(), mm);
    assertThat(p.b()).isCloseTo(o.get("b").asDouble(), mm);
    assertThat(p.c1()).isCloseTo(o.get("c1").asDouble(), mm);
    assertThat(p.c2()).isCloseTo(o.get("c2").asDouble(), mm);
    assertThat(p.c3()).isCloseTo(o.get("c3").asDouble(), mm);
    assertThat(p.c4()).isCloseTo(o.get("c4").asDouble(), mm);
    for (int i = 0; i < 6; i++) {
      assertThat(p.sign(i)).as("%s sign %d", id, i + 1).isEqualTo(o.get("sign_corrections").get(i).asInt());
      double d = ClosedFormIk.wrap(p.offsetRad(i) - Math.toRadians(o.get("offsets_deg").get(i).asDouble()));
      assertThat(Math.abs(d)).as("%s offset %d", id, i + 1).isLessThan(1e-12);
    }
  }

  @ParameterizedTest
  @MethodSource("models")
  void theGeometricConfigFlagsEqualTheClosedFormsOnEveryOpwArm(String id) {
    RobotModel model = RobotDefinitions.load(id);
    if (model.opw().isEmpty()) {
      return;
    }
    ClosedFormIk closed = new ClosedFormIk(model);
    ChainConfig chain = new ChainConfig(new KinematicChain(model));
    for (double[] q : randomJoints(model, FACTS.get(id), org.robotrun.PitScale.samples(2000, 200), 7 + id.hashCode())) {
      assertThat(chain.configOf(q)).as(id).isEqualTo(closed.configOf(q));
    }
  }

  @ParameterizedTest
  @MethodSource("models")
  void ikRoundTripsTwoThousandTargetsInTheirConfig(String id) {
    RobotModel model = RobotDefinitions.load(id);
    IkSolver solver = IkSolver.forModel(model);
    List<double[]> qs = randomJoints(model, FACTS.get(id), org.robotrun.PitScale.samples(2000, 200), 1000 + id.hashCode());
    double[] home = new double[6];
    int missedNearest = 0;
    for (int k = 0; k < qs.size(); k++) {
      double[] q = qs.get(k);
      Transform X = ForwardKinematics.flangePoseInBase(model, q);
      Config c = solver.configOf(q);
      IkResult r = solver.solve(X, c, home);
      assertThat(r).as("%s target %d (%s)", id, k, c).isInstanceOf(IkResult.Solved.class);
      double[] a = ((IkResult.Solved) r).q();
      Transform Y = ForwardKinematics.flangePoseInBase(model, a);
      assertThat(Y.distanceTo(X)).as("%s target %d", id, k).isLessThan(1e-6);
      assertThat(Y.rotationAngleTo(X)).as("%s target %d", id, k).isLessThan(1e-9);
      assertThat(model.firstJointOutsideLimits(a)).as("%s target %d in limits", id, k).isEqualTo(-1);
      assertThat(solver.configOf(a)).as("%s target %d CONFIG", id, k).isEqualTo(c);
      // Nearest to the ground truth is the ground truth itself: a jog or L move never jumps.
      IkResult n = solver.solveNearest(X, q);
      assertThat(n).isInstanceOf(IkResult.Solved.class);
      double[] b = ((IkResult.Solved) n).q();
      double worst = 0;
      for (int i = 0; i < 6; i++) {
        worst = Math.max(worst, Math.abs(b[i] - q[i]));
      }
      if (worst > 1e-6) {
        // Only where several roots of the offset wrist's search lie within rounding of each
        // other (docs/kinematics.md): a neighbour of the same CONFIG, a hair away.
        assertThat(solver.kind()).as("%s target %d nearest (%.2e rad away)", id, k, worst).isEqualTo(OffsetWristIk.KIND);
        assertThat(worst).as("%s target %d nearest", id, k).isLessThan(0.01);
        assertThat(solver.configOf(b)).as("%s target %d nearest CONFIG", id, k).isEqualTo(c);
        missedNearest++;
      }
    }
    assertThat(missedNearest).as(id + ": ground truths not found as the nearest solution").isLessThanOrEqualTo(1);
  }
}
