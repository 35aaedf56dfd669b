package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * ChainConfig's forward direction when the arm stands straight up at q = 0 (the wrist point W
 * on the J1 axis, so "toward W" says nothing): its class comment says f then points toward +x.
 * Two such arms, J2's axis written as +y and as −y (J2 × J1 is then −x and +x before it is
 * oriented), each also bolted on away from the base origin, must call a posture T exactly when W
 * lies in front of the J1 axis along J1's turn of +x; upright exactly, every margin is 0 and the
 * flags are N D B; and U by the documented elbow rule, worked out here from the link positions:
 * ((J3 − J2) × (W − J3)) · (z1 × f) &gt; 0. F is J5 &gt; 0, the turn numbers those of J1, J4, J6.
 */
class ChainConfigUprightTest {

  /** J1 at the base origin about z, J2..J6 straight up the z axis at q = 0; J2 and J3 about {@code pitch}. */
  static RobotModel upright(Vec3 pitch) {
    double[] up = {0, 300, 400, 350, 100, 80};
    Vec3[] axes = {Vec3.Z, pitch, pitch, Vec3.Z, pitch, Vec3.Z};
    List<JointSpec> js = new ArrayList<>();
    List<LinkSpec> links = new ArrayList<>();
    links.add(new LinkSpec("base", List.of()));
    for (int i = 0; i < 6; i++) {
      js.add(new JointSpec("J" + (i + 1), Transform.translation(0, 0, up[i]), axes[i], -3, 3, 3));
      links.add(new LinkSpec("link" + (i + 1), List.of()));
    }
    return new RobotModel("upright", "upright arm", js, Transform.translation(0, 0, 60), Transform.IDENTITY, links,
        java.util.Optional.empty(), false);
  }

  @ParameterizedTest
  @ValueSource(ints = {1, -1, 2, -2})
  void standingUprightTheForwardDirectionIsPlusX(int pitchSign) {
    // |pitchSign| = 2: the same arm bolted on 300 mm behind the base origin (J1's frame moved).
    RobotModel m = upright(Vec3.Y.times(Math.signum(pitchSign)));
    if (Math.abs(pitchSign) == 2) {
      m = MountedArmInvarianceTest.mounted(m, Transform.translation(-300, 120, 50));
    }
    RobotModel arm = m;
    ChainConfig cc = new ChainConfig(new KinematicChain(m));
    Random rnd = new Random(31 + pitchSign);
    int[] seen = new int[8];
    for (int k = 0; k < 300; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = -2.9 + 5.8 * rnd.nextDouble();
      }
      Transform[] L = ForwardKinematics.linkPosesInBase(arm, q);
      Vec3 p1 = L[1].translationVector();
      Vec3 p2 = L[2].translationVector(), p3 = L[3].translationVector(), w = L[5].translationVector();
      Vec3 f = new Vec3(Math.cos(q[0]), Math.sin(q[0]), 0);
      double front = w.minus(p1).dot(f);
      double elbow = p3.minus(p2).cross(w.minus(p3)).dot(Vec3.Z.cross(f));
      if (Math.abs(front) < 1e-6 || Math.abs(elbow) < 1e-6 || Math.abs(Math.sin(q[4])) < 1e-6) {
        continue;
      }
      Config c = cc.configOf(q);
      assertThat(c).as("q = %s", java.util.Arrays.toString(q)).isEqualTo(new Config(q[4] > 0, elbow > 0, front > 0,
          Config.turnOf(q[0]), Config.turnOf(q[3]), Config.turnOf(q[5])));
      seen[(c.flip() ? 4 : 0) + (c.up() ? 2 : 0) + (c.top() ? 1 : 0)]++;
    }
    for (int s = 0; s < 8; s++) {
      assertThat(seen[s]).as("flag triple %d met", s).isPositive();
    }
    // Upright exactly: W on the J1 axis, the elbow stretched, the wrist in line: every margin is 0
    // and each flag needs it above 0.
    assertThat(cc.configOf(new double[6])).isEqualTo(new Config(false, false, false, 0, 0, 0));
    // Bent toward +x at J2 (J1 = 0): in front, T.
    double[] lean = {0, 0.4 * Math.signum(pitchSign), 0, 0, 0.5, 0};
    assertThat(cc.configOf(lean).top()).isTrue();
    lean[1] = -lean[1];
    assertThat(cc.configOf(lean).top()).isFalse();
  }
}
