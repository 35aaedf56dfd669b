package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * {@link KinematicChain} on an arm that no library robot resembles: joints about -y and -x in
 * unrotated frames, a joint about z in a turned frame, and two oblique axes ((1, 2, 2)/3 and
 * (0.6, 0, 0.8)) in frames turned about all three axes, with a turned and moved flange. Every
 * expected pose is composed here with plain 4x4 matrices from the same numbers: the joint frame as
 * Rz(yaw)·Ry(pitch)·Rx(roll) with its offset, then the rotation about the unit axis by Rodrigues'
 * formula (R = cos·I + sin·[a]x + (1 − cos)·a·aᵀ), chained base to flange.
 */
class KinematicChainOracleTest {
  // Per joint: offset (mm), roll/pitch/yaw (rad), axis (not unit: the model normalises).
  static final double[][] XYZ = {{10, -20, 330}, {75, 5, 0}, {0, -12, 440}, {35, 0, 20}, {0, 0, 420}, {0, 18, 80}};
  static final double[][] RPY = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0.3, -0.2, 0.5}, {1.1, 0.4, -0.7}, {-0.6, 0.25, 2.0}};
  static final double[][] AXIS = {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}, {0, 0, 1}, {1, 2, 2}, {0.6, 0, 0.8}};
  static final double[] LOWER = {-2.9, -1.7, -2.4, -3.3, -2.1, -6.2};
  static final double[] UPPER = {2.9, 2.5, 3.5, 3.3, 2.1, 6.2};
  // Flange: offset and rpy in link 6.
  static final double[] F_XYZ = {5, -7, 100};
  static final double[] F_RPY = {0.2, -1.0, 0.4};

  static double[][] rpyMatrix(double[] xyz, double[] rpy) {
    double r = rpy[0], p = rpy[1], y = rpy[2];
    double[][] rx = {{1, 0, 0, 0}, {0, Math.cos(r), -Math.sin(r), 0}, {0, Math.sin(r), Math.cos(r), 0}, {0, 0, 0, 1}};
    double[][] ry = {{Math.cos(p), 0, Math.sin(p), 0}, {0, 1, 0, 0}, {-Math.sin(p), 0, Math.cos(p), 0}, {0, 0, 0, 1}};
    double[][] rz = {{Math.cos(y), -Math.sin(y), 0, 0}, {Math.sin(y), Math.cos(y), 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    double[][] m = mul(rz, mul(ry, rx));
    m[0][3] = xyz[0];
    m[1][3] = xyz[1];
    m[2][3] = xyz[2];
    return m;
  }

  static double[] unit(double[] a) {
    double n = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return new double[] {a[0] / n, a[1] / n, a[2] / n};
  }

  static double[][] rodrigues(double[] axis, double q) {
    double[] a = unit(axis);
    double c = Math.cos(q), s = Math.sin(q);
    double[][] k = {{0, -a[2], a[1]}, {a[2], 0, -a[0]}, {-a[1], a[0], 0}};
    double[][] m = new double[4][4];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        m[i][j] = (i == j ? c : 0) + s * k[i][j] + (1 - c) * a[i] * a[j];
      }
    }
    m[3][3] = 1;
    return m;
  }

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

  static Transform toTransform(double[][] m) {
    return new Transform(m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2],
        m[0][3], m[1][3], m[2][3]);
  }

  static final double[][] IDENTITY = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

  static RobotModel obliqueArm() {
    List<JointSpec> joints = new ArrayList<>();
    List<LinkSpec> links = new ArrayList<>();
    links.add(new LinkSpec("base", List.of()));
    for (int i = 0; i < 6; i++) {
      joints.add(new JointSpec("J" + (i + 1), toTransform(rpyMatrix(XYZ[i], RPY[i])),
          new Vec3(AXIS[i][0], AXIS[i][1], AXIS[i][2]), LOWER[i], UPPER[i], 3.0));
      links.add(new LinkSpec("link" + (i + 1), List.of()));
    }
    return new RobotModel("oblique", "oblique test arm", joints, toTransform(rpyMatrix(F_XYZ, F_RPY)),
        Transform.IDENTITY, links, Optional.empty(), false);
  }

  /** Link poses 0..6 in B, then the flange at [7], from the matrices above. */
  static double[][][] expected(double[] q) {
    double[][][] out = new double[8][][];
    double[][] x = IDENTITY;
    out[0] = x;
    for (int i = 0; i < 6; i++) {
      x = mul(x, mul(rpyMatrix(XYZ[i], RPY[i]), rodrigues(AXIS[i], q[i])));
      out[i + 1] = x;
    }
    out[7] = mul(x, rpyMatrix(F_XYZ, F_RPY));
    return out;
  }

  static double[] randomQ(Random rnd) {
    double[] q = new double[6];
    for (int i = 0; i < 6; i++) {
      q[i] = LOWER[i] + rnd.nextDouble() * (UPPER[i] - LOWER[i]);
    }
    return q;
  }

  static void assertPose(double[] packed, double[][] m, String what) {
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        assertThat(packed[r * 3 + c]).as("%s r%d%d", what, r, c).isCloseTo(m[r][c], within(1e-12));
      }
      assertThat(packed[9 + r]).as("%s translation %d", what, r).isCloseTo(m[r][3], within(1e-9));
    }
  }

  @Test
  void flangePoseOfTheObliqueArmIsTheChainOfMatrices() {
    KinematicChain chain = new KinematicChain(obliqueArm());
    Random rnd = new Random(31);
    double[] x = new double[12];
    for (int k = 0; k < 200; k++) {
      double[] q = randomQ(rnd);
      chain.flangePose(q, x, null);
      assertPose(x, expected(q)[7], "sample " + k);
    }
    // Zero joints: the joint frames and the flange alone.
    double[] zero = new double[6];
    chain.flangePose(zero, x, null);
    assertPose(x, expected(zero)[7], "zero");
  }

  @Test
  void axisLinesAreEachJointsOriginAndAxisInTheBase() {
    // Joint i's axis line: its frame's origin after links 0..i-1, direction = that frame's
    // rotation applied to the unit axis.
    KinematicChain chain = new KinematicChain(obliqueArm());
    Random rnd = new Random(32);
    double[] x = new double[12];
    double[] axes = new double[36];
    for (int k = 0; k < 100; k++) {
      double[] q = randomQ(rnd);
      chain.flangePose(q, x, axes);
      assertPose(x, expected(q)[7], "with axes, sample " + k);
      double[][][] links = expected(q);
      for (int i = 0; i < 6; i++) {
        double[][] frame = mul(links[i], rpyMatrix(XYZ[i], RPY[i]));
        double[] a = unit(AXIS[i]);
        for (int r = 0; r < 3; r++) {
          assertThat(axes[6 * i + r]).as("J%d origin %d", i + 1, r).isCloseTo(frame[r][3], within(1e-9));
          double d = frame[r][0] * a[0] + frame[r][1] * a[1] + frame[r][2] * a[2];
          assertThat(axes[6 * i + 3 + r]).as("J%d direction %d", i + 1, r).isCloseTo(d, within(1e-12));
        }
      }
    }
  }

  @Test
  void linkPosesAreEveryLinkOfTheChainInTheGivenFrame() {
    KinematicChain chain = new KinematicChain(obliqueArm());
    double[][] a = mul(rpyMatrix(new double[] {1200, -300, 50}, new double[] {0.1, 0.2, 0.7}), IDENTITY);
    Transform X_AB = toTransform(a);
    Random rnd = new Random(33);
    Transform[] out = new Transform[7];
    for (int k = 0; k < 100; k++) {
      double[] q = randomQ(rnd);
      chain.linkPoses(X_AB, q, out);
      assertThat(out[0]).isSameAs(X_AB);
      double[][][] links = expected(q);
      for (int i = 1; i <= 6; i++) {
        double[] packed = new double[12];
        KinematicChain.pack(out[i], packed, 0);
        assertPose(packed, mul(a, links[i]), "link " + i + " sample " + k);
      }
    }
  }

  @Test
  void linkPosesOfALibraryArmAgreeWithItsFlangePose() {
    // The library's LR Mate (every joint in an unrotated frame about ±x/±y/±z): link 6 · X_6F is
    // the flange, and in the base frame link 0 is the identity.
    RobotModel m = org.robotrun.io.RobotDefinitions.load("lrmate200id");
    KinematicChain chain = new KinematicChain(m);
    Transform[] out = new Transform[7];
    double[] x = new double[12];
    Random rnd = new Random(34);
    for (int k = 0; k < 50; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = m.joint(i).lowerRad() + rnd.nextDouble() * (m.joint(i).upperRad() - m.joint(i).lowerRad());
      }
      chain.linkPoses(Transform.IDENTITY, q, out);
      chain.flangePose(q, x, null);
      Transform flange = out[6].compose(m.X_6F());
      assertThat(flange.distanceTo(KinematicChain.unpack(x))).isLessThan(1e-9);
      assertThat(flange.rotationAngleTo(KinematicChain.unpack(x))).isLessThan(1e-12);
    }
  }

  @Test
  void limitsAreInclusiveAndNaNIsOutside() {
    KinematicChain chain = new KinematicChain(obliqueArm());
    for (int i = 0; i < 6; i++) {
      assertThat(chain.lower(i)).isEqualTo(LOWER[i]);
      assertThat(chain.upper(i)).isEqualTo(UPPER[i]);
      double[] q = new double[6];
      q[i] = LOWER[i];
      assertThat(chain.withinLimits(q)).as("J%d at its lower limit", i + 1).isTrue();
      q[i] = UPPER[i];
      assertThat(chain.withinLimits(q)).as("J%d at its upper limit", i + 1).isTrue();
      q[i] = Math.nextDown(LOWER[i]);
      assertThat(chain.withinLimits(q)).as("J%d just below", i + 1).isFalse();
      q[i] = Math.nextUp(UPPER[i]);
      assertThat(chain.withinLimits(q)).as("J%d just above", i + 1).isFalse();
      q[i] = Double.NaN;
      assertThat(chain.withinLimits(q)).as("J%d NaN", i + 1).isFalse();
    }
  }

  @Test
  void packedComposeIsTheMatrixProduct() {
    double[][] a = rpyMatrix(new double[] {1, 2, 3}, new double[] {0.3, 0.2, -0.4});
    double[][] b = rpyMatrix(new double[] {-40, 50, 60}, new double[] {-1.2, 0.6, 2.2});
    double[] pa = new double[12];
    double[] pb = new double[12];
    double[] pc = new double[12];
    KinematicChain.pack(toTransform(a), pa, 0);
    KinematicChain.pack(toTransform(b), pb, 0);
    KinematicChain.compose(pa, pb, pc);
    assertPose(pc, mul(a, b), "a·b");
    double[] offset = new double[15];
    KinematicChain.pack(toTransform(b), offset, 3);
    for (int e = 0; e < 12; e++) {
      assertThat(offset[3 + e]).isEqualTo(pb[e]);
    }
    assertPose(pb, b, "pack");
    double[] back = new double[12];
    KinematicChain.pack(KinematicChain.unpack(pb), back, 0);
    assertThat(back).containsExactly(pb);
  }
}
